# Copyright (c) 2026 DF_L1_skeleton contributors.
# SPDX-License-Identifier: LGPL-3.0-or-later
"""Skeletonizes many point clouds on a Dask cluster, one task per file.

    python3 -m df_l1_skeleton.batch INPUT... OUTPUT_DIR [--workers N | --scheduler ADDRESS] [options]

INPUT: folders (every ``.xyz``, ``.pts``, ``.txt``, ``.ply``, ``.off`` file in them, not
recursive) or files; ``--files-from LIST`` adds the paths listed in LIST, one a line.
For each input ``NAME.EXT``, OUTPUT_DIR receives ``NAME.obj`` (``--format``) and
``NAME.json``, the tool's ``--report`` (and ``NAME.segmentation.ply`` with
``--segmentation``): the same files, byte for byte but for the timings, as
``df_l1_skeleton INPUT NAME.obj --report NAME.json``. They are written to temporary files
and renamed together once complete, so a file is either finished or absent.

- Local by default: a ``distributed.LocalCluster`` of ``--workers`` processes (default:
  the cores), one task at a time each, each task on ``--threads`` threads (default: the
  cores divided by the workers). With ``--scheduler ADDRESS`` the tasks go to a running
  Dask scheduler instead (``tcp://host:8786``; dask-jobqueue, dask-kubernetes or
  ``dask-scheduler``/``dask-worker`` start one): its workers must import df_l1_skeleton,
  see INPUT and OUTPUT_DIR at the same paths (a shared file system), and ``--threads``
  (default 1) should be their cores per worker thread.
- Resumable: a file whose output and report exist, the report newer than the input, is
  skipped (``--force`` redoes every file). A file that fails (unreadable, no skeleton...)
  is recorded with the tool's error message and does not stop the others; a rerun tries
  it again.
- A worker that dies (killed, out of memory, its machine lost) loses only its task in
  progress, which Dask gives to another worker; since the outputs appear only complete
  and a finished file is never redone, every file is written exactly once. After the
  batch, temporary files left by killed workers are removed.
- The summary: ``OUTPUT_DIR/summary.jsonl``, one JSON object per input in input order
  (``input``, ``output``, ``report``, ``status`` ok | skipped | failed, ``error``,
  ``seconds``, ``counts``, ``worker``), and a table on stdout; progress on stderr.
- Exit status 0 when every file is ok or skipped, 1 when one failed, 2 on bad usage.

The library's parameters are options as in the tool (``--voxel-resolution 80``,
``--denoising off``...); ``--stage initial`` writes the initial skeleton.
"""

import argparse
import json
import os
import socket
import sys
import time
from typing import Any, Dict, Iterable, List, Optional, Sequence

import df_l1_skeleton as _dfl1

#: The point cloud extensions read in an input folder (the tool's readers).
EXTENSIONS = (".xyz", ".pts", ".txt", ".ply", ".off")
#: The skeleton formats (--format).
FORMATS = ("obj", "ply", "polylines.txt")
_SKELETON_COUNTS = ("vertices", "edges", "components", "cycles", "end_points", "junctions")


def list_inputs(paths: Iterable[str], files_from: Optional[str] = None) -> List[str]:
    """The input files: every cloud file of the folders among ``paths`` (sorted, not
    recursive), the other paths as given, then those listed in ``files_from``."""
    inputs: List[str] = []
    for path in paths:
        if os.path.isdir(path):
            names = sorted(n for n in os.listdir(path) if n.lower().endswith(EXTENSIONS) and not n.startswith("."))
            inputs += [os.path.join(path, n) for n in names if os.path.isfile(os.path.join(path, n))]
        else:
            inputs.append(path)
    if files_from:
        with open(files_from, encoding="utf-8") as f:
            inputs += [line.strip() for line in f if line.strip() and not line.lstrip().startswith("#")]
    return inputs


def output_names(inputs: Sequence[str]) -> List[str]:
    """The output name of every input: its file name without the extension. Two inputs
    with the same name would overwrite each other's outputs: ValueError."""
    names = [os.path.splitext(os.path.basename(p))[0] for p in inputs]
    seen: Dict[str, str] = {}
    for name, path in zip(names, inputs):
        if name in seen:
            raise ValueError(f"'{seen[name]}' and '{path}' would both write {name}.*; rename one or run them apart")
        seen[name] = path
    return names


def _error_text(path: str, error: BaseException) -> str:
    """The tool's message for an error: the library's, starting with the file's name."""
    what = str(error) or type(error).__name__
    if isinstance(error, MemoryError):
        what = "out of memory (try a lower --voxel-resolution or --number-of-samples)"
    return what if what.startswith(path) else f"{path}: {what}"


def _finished(task: Dict[str, Any]) -> Optional[Dict[str, Any]]:
    """The report of a file already done (outputs present, report newer than the input)."""
    needed = [task["output"], task["report"]] + ([task["segmentation"]] if task["segmentation"] else [])
    try:
        if not all(os.path.isfile(p) for p in needed):
            return None
        if os.path.getmtime(task["report"]) < os.path.getmtime(task["input"]):
            return None
        with open(task["report"], encoding="utf-8") as f:
            report = json.load(f)
        return report if report.get("output") == task["output"] else None
    except (OSError, ValueError):
        return None


def _record(task: Dict[str, Any], status: str, report: Optional[Dict[str, Any]] = None,
            error: Optional[str] = None) -> Dict[str, Any]:
    counts = None
    seconds = None
    if report is not None:
        c = report.get("counts", {})
        counts = {"input_points": c.get("input_points")}
        counts.update({k: c.get("skeleton_" + k) for k in _SKELETON_COUNTS})
        seconds = round(sum(report.get("seconds", {}).values()), 6)
    return {"input": task["input"], "output": task["output"], "report": task["report"], "status": status,
            "error": error, "seconds": seconds, "counts": counts, "worker": f"{socket.gethostname()}:{os.getpid()}"}


def process_file(task: Dict[str, Any]) -> Dict[str, Any]:
    """One file, as a Dask task: read, skeletonize, write the outputs and the report
    together, as the tool does; a file already done is not redone. Returns its summary
    record. Never raises for a bad input: the error goes into the record."""
    if not task["force"]:
        report = _finished(task)
        if report is not None:
            # done by an earlier run, or by an attempt of this batch on a worker that
            # died after writing it: not done again
            redone_here = os.path.getmtime(task["report"]) >= task["started"]
            return _record(task, "ok" if redone_here else "skipped", report)
    if task.get("heap_settings", True):
        # the tool's malloc settings, in the worker process (ours while it runs tasks):
        # 40 clouds of 20,000 points took 1.6 times as long without them (doc/python.md)
        _dfl1.keep_large_buffers_on_heap()
    try:
        cloud = _dfl1.read_point_cloud(task["input"])
        skeleton = _dfl1.skeletonize(cloud, stage=task["stage"], threads=task["threads"], seed=task["seed"],
                                     max_memory=task["max_memory"], **task["parameters"])
        _dfl1.write_skeleton(task["output"], skeleton, report=task["report"], segmentation=task["segmentation"])
        return _record(task, "ok", skeleton.report)
    except (ValueError, OSError, MemoryError) as e:
        return _record(task, "failed", error=_error_text(task["input"], e))


class _Progress:
    """One line on stderr: rewritten in place on a terminal, every 5 s otherwise."""

    def __init__(self, total: int, enabled: bool):
        self.total, self.enabled = total, enabled
        self.counts = {"ok": 0, "skipped": 0, "failed": 0}
        self.start = self.last = time.monotonic()
        self.tty = enabled and sys.stderr.isatty()
        self.cluster_seconds: Optional[float] = None

    def started_cluster(self) -> None:
        """From now on the time counts the tasks only; the final line gives both."""
        now = time.monotonic()
        self.cluster_seconds, self.start = now - self.start, now

    def update(self, status: str, final: bool = False) -> None:
        if status:
            self.counts[status] += 1
        if not self.enabled:
            return
        now = time.monotonic()
        if not (self.tty or final or now - self.last >= 5):
            return
        self.last = now
        done = sum(self.counts.values())
        line = (f"df_l1_skeleton.batch: {done}/{self.total} files ({self.counts['ok']} ok, "
                f"{self.counts['skipped']} skipped, {self.counts['failed']} failed), {now - self.start:.1f} s")
        if final and self.cluster_seconds is not None:
            line += f" (after {self.cluster_seconds:.1f} s to start the cluster)"
        sys.stderr.write(("\r" + line + ("\n" if final else "")) if self.tty else line + "\n")
        sys.stderr.flush()


def _remove_leftovers(tasks: Sequence[Dict[str, Any]]) -> None:
    """Removes the temporary files (``.NAME.tmp.PID.N``) that workers killed while
    writing left next to the outputs of this batch."""
    by_dir: Dict[str, set] = {}
    for t in tasks:
        for p in (t["output"], t["report"], t["segmentation"]):
            if p:
                by_dir.setdefault(os.path.dirname(p) or ".", set()).add("." + os.path.basename(p) + ".tmp.")
    for directory, prefixes in by_dir.items():
        try:
            names = os.listdir(directory)
        except OSError:
            continue
        for name in names:
            if name.startswith(".") and any(name.startswith(p) for p in prefixes):
                try:
                    os.remove(os.path.join(directory, name))
                except OSError:
                    pass


def _write_summary(path: str, records: Sequence[Dict[str, Any]]) -> None:
    directory, name = os.path.split(path)
    temporary = os.path.join(directory, f".{name}.tmp.{os.getpid()}")
    with open(temporary, "w", encoding="utf-8") as f:
        for r in records:
            f.write(json.dumps(r) + "\n")
    os.replace(temporary, path)


def _without_prefix(text: str, prefix: str) -> str:
    return text[len(prefix):] if text.startswith(prefix) else text


def print_table(records: Sequence[Dict[str, Any]], out=sys.stdout) -> None:
    """The summary as a table: file, status, skeleton counts, seconds, error."""
    header = ("file", "status", "points", "vertices", "edges", "components", "cycles", "seconds", "error")
    rows = []
    for r in records:
        c = r["counts"] or {}
        rows.append((os.path.basename(r["input"]), r["status"], str(c.get("input_points", "")),
                     str(c.get("vertices", "")), str(c.get("edges", "")), str(c.get("components", "")),
                     str(c.get("cycles", "")), "" if r["seconds"] is None else f"{r['seconds']:.3f}",
                     _without_prefix(r["error"] or "", r["input"] + ": ")[:120]))
    widths = [max(len(h), *(len(row[i]) for row in rows)) if rows else len(h) for i, h in enumerate(header)]
    for row in [header] + rows:
        out.write("  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip() + "\n")


def run_batch(inputs: Sequence[str], output_dir: str, *, client=None, scheduler: Optional[str] = None,
              workers: Optional[int] = None, threads: Optional[int] = None, stage: str = "final",
              format: str = "obj", segmentation: bool = False, seed: int = 0, max_memory=None,
              force: bool = False, parameters: Optional[Dict[str, Any]] = None,
              progress: bool = True, heap_settings: bool = True) -> List[Dict[str, Any]]:
    """Skeletonizes ``inputs`` (files) into ``output_dir``, one Dask task per file, and
    returns the summary records in input order (also written to ``summary.jsonl``).

    The tasks go to ``client`` (a ``distributed.Client``) if given, else to the scheduler
    at ``scheduler``, else to a new ``LocalCluster`` of ``workers`` processes (default:
    the cores) of one thread each, closed at the end. ``threads``: threads per task
    (default: cores // workers locally, 1 on a given scheduler or client).
    ``parameters``: the library's, by name (values as ``skeletonize()`` takes them, or
    their text). ``heap_settings``: the workers keep large buffers on the heap for reuse,
    as the tool does (``keep_large_buffers_on_heap()``; their resident memory then stays
    up to 1 GiB above what they use). See the module's documentation for the files written.
    """
    import distributed

    if format not in FORMATS:
        raise ValueError(f"format must be one of {', '.join(FORMATS)}, got '{format}'")
    names = output_names(inputs)
    os.makedirs(output_dir, exist_ok=True)
    output_dir = os.path.abspath(output_dir)
    started = time.time()
    if threads is None:
        local = client is None and not scheduler
        threads = max(1, (os.cpu_count() or 1) // (workers or os.cpu_count() or 1)) if local else 1
    tasks = [{
        "input": path,
        "output": os.path.join(output_dir, f"{name}.{format}"),
        "report": os.path.join(output_dir, f"{name}.json"),
        "segmentation": os.path.join(output_dir, f"{name}.segmentation.ply") if segmentation else None,
        "stage": stage, "threads": threads, "seed": seed, "max_memory": max_memory,
        "parameters": dict(parameters or {}), "force": force, "started": started, "heap_settings": heap_settings,
    } for path, name in zip(inputs, names)]
    records: List[Optional[Dict[str, Any]]] = [None] * len(tasks)
    bar = _Progress(len(tasks), progress)
    # The files already done are skipped here when this process sees them (a shared
    # file system), without a task; the tasks check again (a worker may see them when
    # this process does not, and a task may run again after its worker died).
    for i, task in enumerate(tasks):
        report = None if force else _finished(task)
        if report is not None:
            records[i] = _record(task, "skipped", report)
            records[i]["worker"] = None
            bar.update("skipped")
    todo = [i for i, r in enumerate(records) if r is None]
    own_cluster = own_client = None
    try:
        if todo and client is None:
            if scheduler:
                client = own_client = distributed.Client(scheduler)
            else:
                own_cluster = distributed.LocalCluster(n_workers=workers or os.cpu_count() or 1, threads_per_worker=1,
                                                       processes=True, dashboard_address=":0")
                client = own_client = distributed.Client(own_cluster)
            bar.started_cluster()
        futures = [client.submit(process_file, tasks[i], key=f"df_l1_skeleton-{i}-{names[i]}", pure=False)
                   for i in todo]
        index = {f.key: i for i, f in zip(todo, futures)}
        for future in distributed.as_completed(futures):
            i = index[future.key]
            try:
                record = future.result()
            except Exception as e:  # e.g. KilledWorker: its workers died too often
                record = _record(tasks[i], "failed", error=_error_text(tasks[i]["input"], e))
            records[i] = record
            bar.update(record["status"])
            future.release()
    finally:
        if own_client is not None:
            own_client.close()
        if own_cluster is not None:
            own_cluster.close()
    bar.update("", final=True)
    _remove_leftovers(tasks)
    _write_summary(os.path.join(output_dir, "summary.jsonl"), records)
    return records


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(prog="python3 -m df_l1_skeleton.batch",
                                description="Skeletonizes every point cloud of the inputs on a Dask cluster, one task per file.",
                                epilog="Outputs: OUTPUT_DIR/NAME.FORMAT and NAME.json (the tool's --report), summary.jsonl. "
                                       "Exit status 0 if every file is ok or skipped, 1 if one failed, 2 on bad usage.")
    p.add_argument("paths", nargs="+", metavar="INPUT... OUTPUT_DIR",
                   help="folders (their .xyz .pts .txt .ply .off files) or files, then the output folder")
    p.add_argument("--files-from", metavar="LIST", help="also the files listed in LIST, one a line")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--workers", type=int, metavar="N", help="local cluster of N worker processes (default: the cores)")
    where.add_argument("--scheduler", metavar="ADDRESS", help="a running Dask scheduler (tcp://host:8786)")
    p.add_argument("--threads", type=int, metavar="N",
                   help="threads per task (default: cores / workers locally, 1 with --scheduler)")
    p.add_argument("--stage", choices=("final", "initial"), default="final", help="the skeleton written (default: final)")
    p.add_argument("--format", choices=FORMATS, default="obj", help="skeleton file format (default: obj)")
    p.add_argument("--segmentation", action="store_true", help="also write NAME.segmentation.ply (the tool's --segmentation)")
    p.add_argument("--seed", type=int, default=0, help="written to the reports (default: 0)")
    p.add_argument("--max-memory", metavar="SIZE", help="refuse a file whose estimated peak memory exceeds SIZE (512M, 4G)")
    p.add_argument("--force", action="store_true", help="redo the files already done")
    p.add_argument("--no-heap-settings", action="store_true",
                   help="leave the workers' malloc as it is (by default they keep large buffers for reuse, as the tool)")
    p.add_argument("--quiet", action="store_true", help="no progress, no table")
    params = p.add_argument_group("parameters of the library (as the tool's options)")
    for name, row in _dfl1.PARAMETERS.items():
        params.add_argument("--" + name.replace("_", "-"), dest="parameter_" + name, metavar=name.upper(),
                            help=f"{row['help']} (default: {row['default_text']})")
    return p


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command line; returns the exit status."""
    parser = _parser()
    args = parser.parse_args(argv)
    if len(args.paths) < 2 and not (args.files_from and args.paths):
        parser.error("expected INPUT... OUTPUT_DIR")
    output_dir = args.paths[-1]
    inputs = list_inputs(args.paths[:-1], args.files_from)
    if not inputs:
        parser.error("no input file (folders are searched for " + " ".join(EXTENSIONS) + ")")
    parameters = {name: getattr(args, "parameter_" + name) for name in _dfl1.PARAMETERS
                  if getattr(args, "parameter_" + name) is not None}
    try:
        # the values are checked once here, with the library's messages, before any task
        _dfl1._core._check_parameters(_dfl1._parameter_texts("batch", parameters))
        _dfl1._max_memory(args.max_memory)
        if args.threads is not None:
            _dfl1._threads(args.threads)
        output_names(inputs)
        records = run_batch(inputs, output_dir, scheduler=args.scheduler, workers=args.workers, threads=args.threads,
                            stage=args.stage, format=args.format, segmentation=args.segmentation, seed=args.seed,
                            max_memory=args.max_memory, force=args.force, parameters=parameters,
                            progress=not args.quiet, heap_settings=not args.no_heap_settings)
    except ValueError as e:
        print(f"df_l1_skeleton.batch: {e}", file=sys.stderr)
        return 2
    if not args.quiet:
        print_table(records)
    return 1 if any(r["status"] == "failed" for r in records) else 0


if __name__ == "__main__":
    sys.exit(main())
