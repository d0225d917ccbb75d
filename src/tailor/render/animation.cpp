/// @file
/// ffmpeg as a child process (posix_spawnp): no shell, so folder names need no quoting.

#include "tailor/render/animation.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "tailor/geometry/error.hpp"

extern char** environ;

namespace tailor {
namespace {

namespace fs = std::filesystem;

/// The last non-empty line of a text file ("" when none).
std::string last_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

/// Runs `args` (args[0] looked up on the PATH) with stdin and stdout on /dev/null and
/// stderr into `log`; returns the exit status (-1 when it could not start or did not exit).
int run_quietly(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

bool ffmpeg_available() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::stringstream folders{std::string(path)};
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (folder.empty()) continue;
    const fs::path candidate = fs::path(folder) / "ffmpeg";
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return true;
  }
  return false;
}

AnimationResult write_animation(const fs::path& directory, double fps, const std::string& prefix) {
  const auto frame = [&](int f) { return directory / fmt::format("{}_{:04d}.png", prefix, f); };
  if (!fs::exists(frame(0))) {
    throw InputError(fmt::format("'{}' has no {}_0000.png to animate", directory.string(), prefix));
  }
  if (!(fps > 0 && fps <= 1000)) {
    throw InputError(fmt::format("animation of '{}': {} frames per second is not in (0, 1000]",
                                 directory.string(), fps));
  }
  AnimationResult result;
  while (fs::exists(frame(result.frames))) ++result.frames;
  if (!ffmpeg_available()) {
    result.reason = "ffmpeg is not installed (Debian package ffmpeg)";
    return result;
  }
  result.path = directory / "animation.mp4";
  const fs::path partial = directory / "animation.mp4.part";
  const fs::path log = directory / "animation.log";
  const int status = run_quietly(
      {"ffmpeg", "-nostdin", "-y", "-loglevel", "error", "-framerate", fmt::format("{}", fps), "-i",
       (directory / (prefix + "_%04d.png")).string(), "-frames:v", std::to_string(result.frames),
       // H.264 in yuv420p needs even sizes.
       "-vf", "scale=trunc(iw/2)*2:trunc(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", "-crf",
       "20", "-movflags", "+faststart", "-f", "mp4", partial.string()},
      log);
  std::error_code ec;
  if (status != 0) {
    const std::string message = last_line(log);
    fs::remove(partial, ec);
    fs::remove(log, ec);
    throw InputError(fmt::format("ffmpeg could not encode the frames of '{}' (exit {}): {}",
                                 directory.string(), status, message));
  }
  fs::remove(log, ec);
  fs::rename(partial, result.path);
  result.written = true;
  return result;
}

}  // namespace tailor
