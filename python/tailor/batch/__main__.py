"""python3 -m tailor.batch check DIR... | simulate SCENE... : a batch on a Dask cluster,
each finished row appended to --out at once (a killed run loses nothing), and rows already
in --out skipped (rerun the same command to resume)."""

import argparse
import csv
import glob
import json
import os
import sys
import time

from . import CHECK_COLUMNS, SIMULATE_COLUMNS, check, scene_name, sequence_key, simulate


class Progress:
    """A one-line progress bar on stderr when it is a terminal; a line per row otherwise
    would flood logs, so then only the end is reported."""

    def __init__(self, total, noun):
        self.total, self.noun, self.done, self.errors = total, noun, 0, 0
        self.start = time.perf_counter()
        self.live = sys.stderr.isatty()

    def update(self, error):
        self.done += 1
        self.errors += bool(error)
        if self.live:
            self._draw("\r")

    def finish(self):
        self._draw("\r" if self.live else "")
        print(file=sys.stderr)

    def _draw(self, prefix):
        width = 30
        filled = width * self.done // max(self.total, 1)
        rate = self.done / max(time.perf_counter() - self.start, 1e-9) * 60
        sys.stderr.write(f"{prefix}[{'#' * filled}{'.' * (width - filled)}] {self.done}/"
                         f"{self.total} {self.noun}  {rate:.1f}/min  errors {self.errors}")
        sys.stderr.flush()


class ResultsFile:
    """results.csv: the names already in it (column `key`), and rows appended one at a
    time, each flushed to the OS as it is written."""

    def __init__(self, path, columns, key):
        self.path, self.columns = path, columns
        self.done = set()
        exists = os.path.exists(path) and os.path.getsize(path) > 0
        if exists:
            try:
                with open(path, newline="") as f:
                    reader = csv.DictReader(f)
                    if reader.fieldnames != columns:
                        raise ValueError(f"columns {reader.fieldnames}")
                    self.done = {row[key] for row in reader}
            except (ValueError, csv.Error) as e:  # UnicodeDecodeError is a ValueError
                raise ValueError(f"{path}: not a results file of this command ({e})") from None
        self.file = open(path, "a", newline="")
        self.writer = csv.DictWriter(self.file, columns)
        if not exists:
            self.writer.writeheader()
            self.file.flush()

    def append(self, row):
        self.writer.writerow({k: ("" if row[k] is None else row[k]) for k in self.columns})
        self.file.flush()

    def close(self):
        self.file.close()


def _sequences(arguments):
    """Each argument is one sequence; a glob that matches folders gives one per folder."""
    out = []
    for argument in arguments:
        folders = sorted(p for p in glob.glob(argument) if os.path.isdir(p))
        out.extend(folders if folders and any(c in argument for c in "*?[") else [argument])
    return out


def _scenes(arguments):
    scenes = []
    for argument in arguments:
        if argument.endswith(".jsonl"):  # one scene dict per line
            with open(argument) as f:
                scenes.extend(json.loads(line) for line in f if line.strip())
        else:
            scenes.append(argument)
    return scenes


def _parser():
    parser = argparse.ArgumentParser(prog="python3 -m tailor.batch", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    for name, help_text in (("check", "check frame sequences as `tailor check` does"),
                            ("simulate", "run a sweep of arm-sleeve scenes")):
        p = commands.add_parser(name, help=help_text)
        p.add_argument("--scheduler", help="address of a running scheduler "
                       "(tcp://host:8786); default: a local cluster")
        p.add_argument("--workers", type=int, help="local cluster size (default: cores)")
        p.add_argument("--out", required=True, help="results CSV (appended; resumed)")
        p.add_argument("--method", default="paper", help="detection preset")
        p.add_argument("--threads", type=int, default=1, help="threads per task")
    p = commands.choices["check"]
    p.add_argument("sequences", nargs="+", metavar="SEQUENCE",
                   help="folder, glob or pattern of one sequence; a glob of folders: each")
    p.add_argument("--obstacle", help="obstacle frames for every sequence")
    p.add_argument("--no-frame-check", action="store_true",
                   help="skip the static intersection check of every frame")
    p = commands.choices["simulate"]
    p.add_argument("scenes", nargs="+", metavar="SCENE",
                   help="scene JSON file, or a .jsonl file with one scene dict per line")
    p.add_argument("--runs", default="runs", help="folder of the runs (one subfolder each)")
    p.add_argument("--frames", type=int, help="frames per run (default: the scene's)")
    return parser


def main(argv=None):
    args = _parser().parse_args(argv)
    try:
        if args.command == "check":
            items = [s if args.obstacle is None else (s, args.obstacle)
                     for s in _sequences(args.sequences)]
            results = ResultsFile(args.out, CHECK_COLUMNS, "sequence")
            todo = [s for s in items if sequence_key(s) not in results.done]
        else:
            # Named before skipping, so that run_NNNN stays the scene's place in the list.
            items = [dict(s, name=scene_name(s, i)) if isinstance(s, dict) else s
                     for i, s in enumerate(_scenes(args.scenes))]
            results = ResultsFile(args.out, SIMULATE_COLUMNS, "scene")
            todo = [s for i, s in enumerate(items) if scene_name(s, i) not in results.done]
    except (OSError, ValueError) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    skipped = len(items) - len(todo)
    if skipped:
        print(f"{skipped} already in {args.out}, {len(todo)} to go", file=sys.stderr)
    progress = Progress(len(todo), "sequences" if args.command == "check" else "runs")

    def on_row(row):
        results.append(row)
        progress.update(row["error"])

    common = dict(scheduler=args.scheduler, workers=args.workers, on_row=on_row,
                  method=args.method, threads=args.threads)
    try:
        if todo and args.command == "check":
            check(todo, check_frames=not args.no_frame_check, **common)
        elif todo:
            simulate(todo, out=args.runs, frames=args.frames, **common)
    finally:
        results.close()
    progress.finish()
    print(f"{progress.done} rows written to {args.out}, {progress.errors} with errors",
          file=sys.stderr)
    return 1 if progress.errors else 0


if __name__ == "__main__":
    sys.exit(main())
