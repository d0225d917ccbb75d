#include "idle_blas_threads.hpp"

#include <dlfcn.h>

namespace tailor::cli {

void stop_idle_blas_threads() {
  // Looked up, not linked: the process may have another BLAS, or none.
  using Shutdown = int (*)();
  if (void* symbol = dlsym(RTLD_DEFAULT, "blas_thread_shutdown_")) {
    reinterpret_cast<Shutdown>(symbol)();
  }
}

}  // namespace tailor::cli
