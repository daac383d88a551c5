#!/usr/bin/env python3
"""Mutation check: does the test suite catch plausible bugs?

Each mutant of mutants.py is a precise textual edit of the sources (file, exact old text, new
text; every old text must occur exactly once, or the mutant is an error, not a survivor). For
each mutant, on a scratch copy of the working tree:
  1. apply the edits, rebuild the targets its quick tests need (ninja -j2, ccache when present);
  2. run its quick tests (test binary + gtest filter, listed with the mutant): a failure kills it;
  3. only if they all pass, build everything and run the whole ctest suite; a test that fails
     there and passed on the unmutated tree kills it;
  4. restore the files.
A mutant that does not compile is an error (the edit is wrong), not a kill. Prints a summary and
writes scripts/mutation/last_result.txt (or --result FILE).

  scripts/mutation/mutate.py                   # every mutant
  scripts/mutation/mutate.py ward-norm rgl-sigma  # some, by id
  scripts/mutation/mutate.py --list            # ids and bugs
  scripts/mutation/mutate.py --quick-only      # skip step 3 (survivors of step 2 stay "survived?")

The scratch copy (default $TMPDIR/brdfkit-mutation) is kept between runs so its build is
incremental; the first run builds the whole project there. Run it niced on a shared machine:
  nice -n 5 scripts/mutation/mutate.py
Python 3 standard library only.
"""

import argparse
import datetime
import filecmp
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(HERE))
from mutants import MUTANTS  # noqa: E402

# Not copied: build outputs, git metadata, this script's log, npm packages (linked instead: the
# export tests and the report assets read them from the source tree).
EXCLUDED_TOP = {".git", "node_modules", "out", "results", "mutation.log"}
LINKED_TOP = {"node_modules"}


class MutantError(Exception):
    """A mutant that cannot be run as written (its old text is absent or repeated, it does not compile)."""


def log(msg):
    print(f"[{datetime.datetime.now():%H:%M:%S}] {msg}", flush=True)


def excluded(rel_parts):
    top = rel_parts[0]
    return top in EXCLUDED_TOP or top.startswith("build") or "__pycache__" in rel_parts


def sync_tree(src: Path, dst: Path):
    """Mirrors src into dst (files only), copying only what differs, so the scratch build stays
    incremental. Build folders and .git are left out."""
    dst.mkdir(parents=True, exist_ok=True)
    seen = set()
    for dirpath, dirnames, filenames in os.walk(src):
        rel_dir = Path(dirpath).relative_to(src)
        keep = []
        for d in dirnames:
            parts = (rel_dir / d).parts
            if not excluded(parts):
                keep.append(d)
        dirnames[:] = keep
        for f in filenames:
            rel = rel_dir / f
            if excluded(rel.parts):
                continue
            seen.add(rel)
            s, d = src / rel, dst / rel
            if d.exists() and not d.is_symlink() and filecmp.cmp(s, d, shallow=False):
                continue
            # A fresh mtime (not the source's, which may be older than the scratch build's
            # objects) so ninja rebuilds what changed.
            d.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(s, d)
            shutil.copymode(s, d)
    for dirpath, dirnames, filenames in os.walk(dst):
        rel_dir = Path(dirpath).relative_to(dst)
        dirnames[:] = [d for d in dirnames if not excluded((rel_dir / d).parts)]
        for f in filenames:
            rel = rel_dir / f
            if not excluded(rel.parts) and rel not in seen:
                (dst / rel).unlink()
    for name in LINKED_TOP:
        link, target = dst / name, src / name
        if target.exists() and not link.exists():
            link.symlink_to(target)


def run(cmd, cwd, log_file, timeout=None):
    """Runs cmd, appending its output to log_file; returns (exit code, output). 124 on timeout."""
    try:
        p = subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           errors="replace", timeout=timeout)
        out, rc = p.stdout, p.returncode
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
        out += f"\n[timed out after {timeout} s]\n"
        rc = 124
    with open(log_file, "a") as f:
        f.write(f"$ {' '.join(map(str, cmd))}\n{out}\n")
    return rc, out


class Scratch:
    def __init__(self, path: Path, jobs: int, log_file: Path, data_dir: Path):
        self.root = path
        self.build = path / "build"
        self.jobs = jobs
        self.log_file = log_file
        self.data_dir = data_dir
        self.baseline_failures = None  # tests failing on the unmutated tree (full suite), once known

    def prepare(self):
        log(f"syncing {ROOT} -> {self.root}")
        sync_tree(ROOT, self.root)
        if not (self.build / "build.ninja").exists():
            cmd = ["cmake", "-S", str(self.root), "-B", str(self.build), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
                   "-DBRDFKIT_BENCH=OFF", f"-DBRDFKIT_DATA_DIR={self.data_dir}"]
            rc, out = run(cmd, self.root, self.log_file)
            if rc != 0:
                raise SystemExit(f"cmake failed in {self.build}:\n{out[-3000:]}")

    def ninja(self, targets=()):
        return run(["ninja", "-C", str(self.build), f"-j{self.jobs}", *targets], self.root, self.log_file)

    def binary(self, target):
        return self.build / "tests" / target if target != "brdfkit_cli" else self.build / "brdfkit"

    def quick_tests(self, quick, timeout):
        """Runs (binary, gtest filter) pairs; returns the failing ones as strings, [] when all pass."""
        failed = []
        for target, gfilter in quick:
            rc, out = run([str(self.binary(target)), f"--gtest_filter={gfilter}", "--gtest_brief=1"], self.build,
                          self.log_file, timeout)
            if rc == 0 and "[  PASSED  ]" in out and not re.search(r"\[  PASSED  \] 0 tests", out):
                continue
            if rc == 0:
                raise MutantError(f"quick test {target} --gtest_filter={gfilter} ran no test")
            names = re.findall(r"^\[  FAILED  \] ([\w/.]+)", out, re.M)
            what = ", ".join(sorted(set(names))) if names else ("timeout" if rc == 124 else f"exit {rc}")
            failed.append(f"{target}: {what}")
        return failed

    def full_suite(self, timeout):
        """Whole ctest suite; returns the set of failing test names."""
        rc, out = run(["ctest", "--test-dir", str(self.build), "-j", str(self.jobs), "--timeout", str(timeout)],
                      self.root, self.log_file)
        # Only the list after "The following tests FAILED:" (the "did not run" list names the
        # DISABLED_ tests the same way).
        _, _, failed_list = out.partition("The following tests FAILED:")
        failed = set(re.findall(r"^\s*\d+ - (\S+) ", failed_list, re.M))
        if rc != 0 and not failed:
            failed.add(f"ctest exit {rc}")
        return failed


def apply_edits(root: Path, edits):
    """Applies (file, old, new) edits; returns the original texts. Each old text must occur once."""
    originals = {}
    try:
        for path, old, new in edits:
            f = root / path
            if not f.exists():
                raise MutantError(f"{path}: no such file")
            current = f.read_text()
            originals.setdefault(path, current)
            n = current.count(old)
            if n != 1:
                raise MutantError(f"{path}: the old text occurs {n} times (must be exactly once): {old[:80]!r}")
            f.write_text(current.replace(old, new, 1))
    except MutantError:
        restore(root, originals)
        raise
    return originals


def restore(root: Path, originals):
    for path, text in originals.items():
        (root / path).write_text(text)


def check_mutants(selected):
    ids = [m["id"] for m in MUTANTS]
    dup = {i for i in ids if ids.count(i) > 1}
    if dup:
        raise SystemExit(f"duplicate mutant ids: {sorted(dup)}")
    for m in selected:
        for key in ("id", "family", "bug", "edits", "quick"):
            if key not in m:
                raise SystemExit(f"mutant {m.get('id', '?')}: missing field '{key}'")


def mutant_targets(m):
    return sorted({t for t, _ in m["quick"]})


def run_mutant(s: Scratch, m, args):
    """Returns (status, detail): killed / survived / error."""
    try:
        originals = apply_edits(s.root, m["edits"])
    except MutantError as e:
        return "error", str(e)
    try:
        rc, out = s.ninja(mutant_targets(m))
        if rc != 0:
            return "error", "does not compile: " + first_error(out)
        failed = s.quick_tests(m["quick"], args.test_timeout)
        if failed:
            return "killed", "quick: " + "; ".join(failed)
        if args.quick_only:
            return "survived?", "quick tests pass (full suite not run: --quick-only)"
        if s.baseline_failures is None:
            restore(s.root, originals)
            originals = {}
            s.baseline_failures = baseline_full(s, args)
            originals = apply_edits(s.root, m["edits"])
        rc, out = s.ninja()
        if rc != 0:
            return "error", "does not compile (full build): " + first_error(out)
        failed = s.full_suite(args.test_timeout) - s.baseline_failures
        if failed:
            return "killed", "full suite: " + ", ".join(sorted(failed)[:6]) + (" ..." if len(failed) > 6 else "")
        return "survived", "quick tests and the full suite pass"
    except MutantError as e:
        return "error", str(e)
    finally:
        restore(s.root, originals)


def baseline_full(s: Scratch, args):
    log("baseline: full build and ctest on the unmutated tree (tests failing here cannot kill a mutant)")
    rc, out = s.ninja()
    if rc != 0:
        raise SystemExit("the unmutated tree does not build in the scratch copy:\n" + first_error(out))
    failed = s.full_suite(args.test_timeout)
    log(f"baseline: {len(failed)} failing test(s){': ' + ', '.join(sorted(failed)) if failed else ''}")
    return failed


def first_error(out):
    lines = [l for l in out.splitlines() if "error" in l.lower()]
    return (lines[0] if lines else out.strip().splitlines()[-1] if out.strip() else "?")[:300]


def baseline_quick(s: Scratch, selected, args):
    """The quick tests must pass on the unmutated tree, or they prove nothing."""
    targets = sorted({t for m in selected for t, _ in m["quick"]})
    rc, out = s.ninja(targets)
    if rc != 0:
        raise SystemExit("the unmutated tree does not build in the scratch copy:\n" + first_error(out))
    bad = []
    for m in selected:
        try:
            failed = s.quick_tests(m["quick"], args.test_timeout)
        except MutantError as e:
            failed = [str(e)]
        if failed:
            bad.append(f"{m['id']}: {'; '.join(failed)}")
    return bad


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("ids", nargs="*", help="mutant ids (default: all)")
    ap.add_argument("--list", action="store_true", help="list the mutants and exit")
    ap.add_argument("--scratch", type=Path, default=Path(tempfile.gettempdir()) / "brdfkit-mutation")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--quick-only", action="store_true", help="do not run the full suite on quick-test survivors")
    ap.add_argument("--test-timeout", type=int, default=600, help="seconds per test run")
    ap.add_argument("--data-dir", type=Path, default=(ROOT / ".." / "shared" / "data").resolve())
    ap.add_argument("--result", type=Path, default=HERE / "last_result.txt")
    args = ap.parse_args()

    if args.list:
        for m in MUTANTS:
            print(f"{m['id']:32} {m['family']:28} {m['bug']}")
        return 0
    unknown = [i for i in args.ids if i not in {m["id"] for m in MUTANTS}]
    if unknown:
        raise SystemExit(f"unknown mutant id(s): {', '.join(unknown)} (see --list)")
    selected = [m for m in MUTANTS if not args.ids or m["id"] in args.ids]
    check_mutants(selected)

    # A TERM or HUP unwinds like an exception, so run_mutant restores the mutated files (a killed
    # run also leaves nothing behind: the next run's sync copies every differing file back).
    for sig in (signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, lambda signum, frame: sys.exit(128 + signum))
    args.scratch.mkdir(parents=True, exist_ok=True)
    log_file = args.scratch / "mutation.log"
    log_file.write_text("")
    s = Scratch(args.scratch, args.jobs, log_file, args.data_dir)
    t0 = time.time()
    s.prepare()
    log(f"building the quick tests' targets on the unmutated tree (log: {log_file})")
    bad = baseline_quick(s, selected, args)
    if bad:
        print("quick tests fail on the unmutated tree (fix them or the mutant list first):\n  " + "\n  ".join(bad))
        return 2

    results = []
    for k, m in enumerate(selected, 1):
        t = time.time()
        log(f"[{k}/{len(selected)}] {m['id']}: {m['bug']}")
        status, detail = run_mutant(s, m, args)
        results.append((m, status, detail, time.time() - t))
        log(f"    {status.upper()} ({time.time() - t:.0f} s): {detail}")
    # Leave the scratch build matching the unmutated tree.
    s.ninja([t for m in selected for t in mutant_targets(m)])

    counts = {}
    for _, status, _, _ in results:
        counts[status] = counts.get(status, 0) + 1
    lines = [f"brdfkit mutation check, {datetime.datetime.now():%Y-%m-%d %H:%M}, {len(results)} mutants, "
             f"{time.time() - t0:.0f} s",
             "summary: " + ", ".join(f"{v} {k}" for k, v in sorted(counts.items())), ""]
    for m, status, detail, secs in results:
        lines.append(f"{status.upper():9} {m['id']:32} {m['family']:28} {m['bug']}")
        lines.append(f"          {detail} ({secs:.0f} s)")
    text = "\n".join(lines) + "\n"
    print("\n" + text)
    args.result.write_text(text)
    log(f"wrote {args.result}")
    return 0 if all(st == "killed" for _, st, _, _ in results) else 1


if __name__ == "__main__":
    sys.exit(main())
