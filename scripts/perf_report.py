#!/usr/bin/env python3
"""Runs the benchmark suite and regenerates the published results.

    scripts/perf_report.py                 # Release build in build-perf/, full run, docs updated
    scripts/perf_report.py --quick         # smoke sizes, 1 repetition; output in the build folder
    scripts/perf_report.py --json FILE     # results from a saved run's JSON, no run

A run writes Google Benchmark's JSON to BUILD/bench.json (never into docs/: 2 MB of raw samples;
scripts/perf_compare.py compares saved runs), then writes docs/perf/results.csv (one line per row of the results
table) and replaces the region between `<!-- bench:tables:begin -->` and
`<!-- bench:tables:end -->` in docs/performance.md: the run's command, commit, build and machine,
the results table (cardemo beside Box2D 2.4.1 from the same process) and the speed targets. Then it
runs every cardemo_tradeoff_* study and redraws its plot (`scripts/plot_tradeoffs.py BUILD --run`).

Times are CPU time per item, the fastest repetition (a burst of load from other processes raises a
sample, not the minimum) and the median of the repetitions. With --processes P the repetitions are
shared among P processes run one after the other, so that no row's samples all come from one
process: on a shared VM one core can run a row half again slower for minutes at a time.
"""
import argparse
import csv
import json
import re
import shlex
import statistics
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CSV_PATH = ROOT / "docs" / "perf" / "results.csv"
DOC = ROOT / "docs" / "performance.md"
BEGIN, END = "<!-- bench:tables:begin -->", "<!-- bench:tables:end -->"


def run(cmd, **kw):
    print("+", " ".join(str(c) for c in cmd), flush=True)
    return subprocess.run(cmd, check=True, **kw)


def build(build_dir):
    run(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
         "-DCARDEMO_BUILD_TESTS=OFF", "-DCARDEMO_BUILD_BENCH=ON"])
    targets = ["cardemo_bench", "cardemo"]
    tradeoff_sources = sorted((ROOT / "bench" / "tradeoff").glob("*.cpp"))
    targets += [f"cardemo_tradeoff_{p.stem}" for p in tradeoff_sources]
    run(["cmake", "--build", str(build_dir), "--target", *targets, "-j2"])


def git_commit():
    """The checked-out commit, marked `+changes` when the tree differs from it."""
    try:
        head = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"],
                              capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", str(ROOT), "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "?"
    return head + ("+changes" if dirty else "")


def cpu_model():
    try:
        for line in open("/proc/cpuinfo", encoding="utf-8"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "?"


def box2d_package():
    """The installed Debian package of Box2D (its own b2_version of 2.4.1 still reads 2.4.0)."""
    try:
        return subprocess.run(["dpkg-query", "-W", "-f=${Version}", "libbox2d-dev"],
                              capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def run_bench(build_dir, quick, repetitions, bench_filter, out_json, processes=1):
    """Runs the suite in `processes` processes, one after the other, sharing the repetitions, and
    writes their runs to `out_json` as one Google Benchmark JSON (the first process's context, with
    this script's command, the commit, the CPU model and the Box2D package added)."""
    processes = 1 if quick else max(1, min(processes, repetitions))
    merged = None
    for p in range(processes):
        part = out_json.with_suffix(f".part{p}.json")
        cmd = [str(build_dir / "bench" / "cardemo_bench"), "--benchmark_format=json",
               f"--benchmark_out={part}", "--benchmark_out_format=json"]
        if quick:
            cmd += ["--smoke", "--benchmark_min_time=0.001"]
        else:
            # Repetitions interleaved at random across the run: a burst of load from other
            # processes then slows one sample of many benchmarks, not every sample of a few.
            share = repetitions // processes + (1 if p < repetitions % processes else 0)
            cmd += [f"--benchmark_repetitions={share}", "--benchmark_min_time=0.2",
                    "--benchmark_enable_random_interleaving=true"]
        if bench_filter:
            cmd.append(f"--benchmark_filter={bench_filter}")
        run(cmd, stdout=subprocess.DEVNULL)
        data = json.loads(part.read_text())
        part.unlink()
        if merged is None:
            merged = data
        else:
            merged["benchmarks"] += data["benchmarks"]
    ctx = merged.setdefault("context", {})
    ctx["processes"] = processes
    ctx["report_command"] = "scripts/perf_report.py " + shlex.join(sys.argv[1:])
    ctx["git_commit"] = git_commit()
    ctx["cpu_model"] = cpu_model()
    ctx["box2d_package"] = box2d_package()
    tmp = out_json.with_suffix(".tmp")
    tmp.write_text(json.dumps(merged, indent=2) + "\n")
    tmp.replace(out_json)


class Results:
    """Per benchmark: the fastest repetition (least CPU time per item) with its counters, and the
    time per item of every repetition."""

    def __init__(self, data):
        self.context = data.get("context", {})
        self.rows = {}
        self.times = {}
        for b in data["benchmarks"]:
            if b.get("error_occurred") or b.get("run_type") == "aggregate":
                continue
            name = re.sub(r"/iterations:\d+", "", b.get("run_name", b["name"]))
            self.times.setdefault(name, []).append(self.per_item(b))
            old = self.rows.get(name)
            if old is None or self.per_item(b) < self.per_item(old):
                self.rows[name] = b

    @staticmethod
    def per_item(b):
        if b.get("items_per_second"):
            return 1e9 / b["items_per_second"]
        scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
        return b["cpu_time"] * scale

    def ns(self, name):
        """(fastest, median) ns per item, or (None, None) when the row did not run."""
        times = self.times.get(name)
        return (min(times), statistics.median(times)) if times else (None, None)

    def counter(self, name, key):
        b = self.rows.get(name)
        return None if b is None else b.get(key)

    def has(self, name):
        return name in self.rows

    def widest_path(self, prefix):
        """The batch path the library picks on this CPU: the widest one that ran."""
        return next((p for p in ("avx512", "avx2", "portable") if self.has(f"{prefix}/{p}")), None)


@dataclass
class Target:
    """A speed target on one row: `value` in the row's unit, or a least Box2D / cardemo ratio."""
    text: str
    value: float
    kind: str  # "max" (the value at most), "min" (at least), "ratio" (Box2D / cardemo at least)
    why: str  # what limits it, printed only when the target is not met


@dataclass
class Row:
    what: str
    size: str
    unit: str
    ours: tuple  # (fastest, median) in `unit`; median None when not timed
    box2d: str  # Box2D's counterpart, "" when it has none
    theirs: tuple  # Box2D's (fastest, median), or (None, None)
    target: Target = None

    def ratio(self, k=0):
        """Box2D / cardemo: above 1, cardemo is faster (or smaller)."""
        a, b = self.theirs[k], self.ours[k]
        if a is None or b is None or b == 0:
            return None
        return b / a if self.unit == "frames/s" else a / b

    def verdicts(self):
        """Whether the target is met on the fastest repetition and on the median (None: not timed)."""
        out = []
        for k in (0, 1):
            t = self.target
            x = self.ratio(k) if t.kind == "ratio" else self.ours[k]
            out.append(None if x is None else (x <= t.value if t.kind == "max" else x >= t.value))
        return out

    def off(self):
        """How far the fastest repetition is from the target, as "47% off" or "2.3x off"."""
        t = self.target
        x = self.ratio(0) if t.kind == "ratio" else self.ours[0]
        if x is None:
            return ""
        factor = x / t.value if t.kind == "max" else t.value / x
        return f"{(factor - 1) * 100:.0f}% off" if factor < 1.5 else f"{factor:.1f}x off"


# Why each target is where it is, printed beside it only when it is not met (the measurements
# behind each sentence are in the commits that made them; the ideas not kept in lab/README.md).
WHY = {
    "manifoldObb2": "one pair is one chain of dependent operations with about 2.2 mispredicted "
                    "branches (callgrind); every branch-free form tried was slower at 1k; "
                    "`manifoldObb2Batch` meets both targets",
    "manifoldObb2Batch": "a group of lanes is one chain of dependent operations (two clips, each "
                         "ending in a division)",
    "collidePolygons": "Box2D's 1k row gains from the repeated pairs (branch predictor); the "
                       "quadrilateral kernel has no data-dependent branch to gain",
    "overlapObb3": "one pair's chain: pose, face gaps, edge gaps, the pick",
    "collideObb3": "one pair's chain: pose, face gaps, edge gaps, the pick, a root and a division",
    "overlapObb2Batch": "the float pass alone takes 0.44-0.48 ns a box at 64k, which leaves about "
                        "0.06 ns a box to read and decide in double the tenth of boxes near touching",
    "collideObb2Batch": "memory: a loop that only reads the kernel's 48 bytes and writes its 24 "
                        "bytes a box takes 0.79-0.80 ns at 64k",
    "overlapObb3Batch": "the boxes near touching (8 %) go on to the double kernel one by one",
    "separationObb3Batch": "it returns the double gap, so no float shortcut; its A-frame filter "
                           "(pose, nine face and nine edge gaps, a root, a division) is the time; "
                           "not memory-bound at 64k",
    "query/lot": "slow spells of the shared VM raise the median; the fastest repetition is the "
                 "code's figure",
    "query/random": "boxes at any heading reach 5.16 m both ways, so a window spans more rows of "
                    "cells than in the lot (2.96 boxes a query against 2.30); slow spells of the "
                    "shared VM raise the median",
    "memory": "cells and row bits grow with the layout's spread",
    "step": "half the lot drive's steps resolve a contact; a loaded machine pushes the median over",
    "load": "first touches of the 40 MB the parse and the World fill: page faults cost most",
    "replay": "the replay's steps are World::step's",
}


def ns_target(value, key):
    return Target(f"<= {value:g} ns", value, "max", WHY[key])


def rows_of(r):
    """Every row of the results table, in order, from one run."""
    rows = []

    def add(what, size, unit, ours, box2d="", theirs=(None, None), target=None):
        if ours[0] is not None or theirs[0] is not None:
            rows.append(Row(what, size, unit, ours, box2d, theirs, target))

    pair_targets = {("manifoldObb2", "1k"): 10.0, ("manifoldObb2", "1M"): 20.0,
                    ("manifoldObb2Batch", "1k"): 10.0, ("manifoldObb2Batch", "1M"): 20.0,
                    ("overlapObb3", "1k"): 25.0, ("collideObb3", "1k"): 40.0}
    for query, label, box2d_row, box2d in (
            ("overlapObb2", "`overlapObb2`", "overlapObb2", "`b2TestOverlap`"),
            ("collideObb2", "`collideObb2` (depth and normal)", None, ""),
            ("manifoldObb2", "`manifoldObb2`", "collidePolygons", "`b2CollidePolygons`"),
            ("collidePolygons", "`collidePolygons`, quadrilaterals", "collidePolygons",
             "`b2CollidePolygons`"),
            ("overlapObb3", "`overlapObb3`", None, ""),
            ("collideObb3", "`collideObb3`", None, ""),
            ("manifoldObb2Batch", "`manifoldObb2Batch`, all pairs at once", "collidePolygons",
             "`b2CollidePolygons`, one at a time")):
        for size in ("1k", "1M"):
            t = pair_targets.get((query, size))
            target = ns_target(t, query) if t else None
            if query == "collidePolygons":
                target = Target(">= 2x Box2D", 2.0, "ratio", WHY[query])
            theirs = r.ns(f"narrow/{box2d_row}/{size}/box2d") if box2d_row else (None, None)
            add(label, f"{size} pairs", "ns", r.ns(f"narrow/{query}/{size}/cardemo"), box2d, theirs,
                target)
    batch_targets = {"overlapObb2": 0.5, "collideObb2": 1.0, "overlapObb3": 5.0, "separationObb3": 5.0}
    for query, box2d in (("overlapObb2", "`b2TestOverlap`, one at a time"),
                         ("collideObb2", "`b2CollidePolygons`, one at a time"),
                         ("overlapObb3", ""), ("separationObb3", "")):
        for size in ("64k", "1M"):
            prefix = f"batch/{query}/{size}"
            path = r.widest_path(prefix)
            if path is None:
                continue
            t = batch_targets[query] if size == "64k" else None
            add(f"`{query}Batch`, one box against many, {path}", f"{size} boxes", "ns",
                r.ns(f"{prefix}/{path}"), box2d, r.ns(f"{prefix}/box2d"),
                ns_target(t, f"{query}Batch") if t else None)
    for layout in ("lot", "random"):
        for size in ("1k", "1M"):
            add(f"grid query, {layout}", f"{size} cars", "ns", r.ns(f"broad/query/{layout}/{size}/cardemo"),
                "`b2DynamicTree` query", r.ns(f"broad/query/{layout}/{size}/box2d"),
                ns_target(20.0, f"query/{layout}") if size == "1M" else None)
    for layout in ("lot", "random"):
        add(f"grid build, {layout}, per car", "1M cars", "ns", r.ns(f"broad/build/{layout}/1M/cardemo"),
            "`b2DynamicTree` inserts", r.ns(f"broad/build/{layout}/1M/box2d"))
    for layout in ("lot", "random"):
        name = f"broad/query/{layout}/1M"
        add(f"grid memory, {layout}", "1M cars", "B/car",
            (r.counter(f"{name}/cardemo", "bytes_per_car"), None), "`b2DynamicTree` nodes, at least",
            (r.counter(f"{name}/box2d", "bytes_per_car"), None),
            Target("<= 64 B/car", 64.0, "max", WHY["memory"]))
    for size in ("1k", "100k", "1M"):
        add("`World::step`, lot drive", f"{size} parked cars", "ns", r.ns(f"step/lot/{size}/cardemo"),
            "`b2World::Step`, the lot in one static body", r.ns(f"step/lot/{size}/box2d"),
            ns_target(200.0, "step") if size == "1M" else None)
    add("(the car alone, no parked car)", "", "ns", (None, None),
        "`b2World::Step`: its solver and bookkeeping", r.ns("step/lot/1k/box2d_alone"))
    fast, median = r.ns("load/scene+world/100k/cardemo")
    if fast is not None:
        add("load a scene: JSON parsed (simdjson), World built", "100k cars", "ms",
            (fast / 1e6, median / 1e6), target=Target("<= 300 ms", 300.0, "max", WHY["load"]))
    for replay in ("demo", "large-lot"):
        fast, median = r.ns(f"replay/{replay}/cardemo")
        if fast is None:
            continue
        target = Target(">= 5 million frames/s", 5e6, "min", WHY["replay"]) if replay == "demo" else None
        add(f"headless replay, `{replay}.replay`", "", "frames/s", (1e9 / fast, 1e9 / median),
            target=target)
    return rows


def fmt(x, unit=""):
    if x is None:
        return ""
    if unit == "frames/s":
        return f"{x / 1e6:.1f} M frames/s"  # more digits of a noisy rate would be false precision
    suffix = f" {unit}" if unit else ""
    if x >= 10000:
        return f"{float(f'{x:.3g}'):,.0f}{suffix}"  # three significant figures: the noise is larger
    if x >= 100:
        return f"{x:,.0f}{suffix}"
    if x >= 10:
        return f"{x:.1f}{suffix}"
    return f"{x:.2f}{suffix}"


def ratio_text(x):
    return "" if x is None else f"{fmt(x)}x"


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(out)


def results_table(rows):
    body = []
    for row in rows:
        bound = ">= " if row.unit == "B/car" else ""  # Box2D's memory is a lower bound
        theirs = fmt(row.theirs[0], row.unit)
        ratio = ratio_text(row.ratio(0))
        body.append([row.what, row.size, fmt(row.ours[0], row.unit), fmt(row.ours[1], row.unit),
                     row.box2d, bound + theirs if theirs else "", bound + ratio if ratio else ""])
    return table(["what", "size", "cardemo", "cardemo, median", "Box2D 2.4.1 counterpart",
                  "Box2D", "Box2D / cardemo"], body)


def targets_table(rows):
    body = []
    last_why = None
    for row in rows:
        if row.target is None:
            continue
        measured = fmt(row.ours[0], row.unit)
        if row.ours[1] is not None:
            measured += f" / {fmt(row.ours[1], row.unit)}"
        if row.target.kind == "ratio":
            measured = f"{ratio_text(row.ratio(0))} / {ratio_text(row.ratio(1))}"
        fast_ok, median_ok = row.verdicts()
        if fast_ok and median_ok in (True, None):
            status, why = "met", ""
        elif fast_ok:
            status, why = "met on the fastest, not on the median", row.target.why
        else:
            status, why = f"not met ({row.off()})", row.target.why
        shown = "as above" if why and why == last_why else why
        last_why = why
        body.append([row.what, row.size, row.target.text, measured, status, shown])
    return table(["what", "size", "target", "fastest / median", "status", "what limits it"], body)


def source_text(ctx):
    """Which run the tables come from: its command and commit, the build and the machine, all read
    from the benchmark's JSON context."""
    processes = ctx.get("processes", 1)
    shared = f", shared among {processes} processes run one after the other" if processes > 1 else ""
    isa = {}
    for entry in filter(None, (ctx.get("isa_flags") or "").split(" | ")):
        name, flags = entry.split(": ", 1)
        isa.setdefault(flags, []).append(f"`{name}`")
    isa_text = "; ".join(f"{', '.join(names)}: `{flags}`" for flags, names in isa.items())
    package = ctx.get("box2d_package")
    return "\n".join([
        f"- Run: `{ctx.get('report_command', '?')}` at commit {ctx.get('git_commit', '?')}; CPU "
        f"time per item, the fastest and the median of the repetitions{shared}.",
        f"- Build: {ctx.get('compiler', '?')}, {ctx.get('build_type', '?')}, "
        f"`{ctx.get('cxx_flags', '?')}`, no `-march`; only these files add flags, each run after a "
        f"CPU check: {isa_text or '(not in this run)'}.",
        f"- Machine: {ctx.get('cpu_model', '?')}, {ctx.get('num_cpus', '?')} cores at "
        f"{ctx.get('mhz_per_cpu', '?')} MHz as reported, batch path {ctx.get('batch_path', '?')}; "
        f"Box2D {ctx.get('box2d', '?')}" + (f" (Debian's libbox2d {package})" if package else "") + ".",
    ])


def region_text(r, rows):
    return "\n".join([BEGIN, "", source_text(r.context), "", results_table(rows), "",
                      "### Speed targets", "", targets_table(rows), "", END])


def write_csv(rows, path):
    def num(x):
        return "" if x is None else f"{x:.4g}"

    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(".tmp")
    with open(tmp, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["what", "size", "unit", "cardemo", "cardemo_median", "box2d_counterpart", "box2d",
                    "box2d_median", "box2d_over_cardemo", "target", "met_fastest", "met_median"])
        for row in rows:
            verdicts = row.verdicts() if row.target else [None, None]
            w.writerow([row.what.replace("`", ""), row.size, row.unit, num(row.ours[0]),
                        num(row.ours[1]), row.box2d.replace("`", ""), num(row.theirs[0]),
                        num(row.theirs[1]), num(row.ratio(0)),
                        row.target.text if row.target else "",
                        *("" if v is None else ("yes" if v else "no") for v in verdicts)])
    tmp.replace(path)


def write_doc(region, doc):
    text = doc.read_text(encoding="utf-8")
    if BEGIN not in text or END not in text:
        sys.exit(f"{doc}: the markers {BEGIN} and {END} are missing")
    start, end = text.index(BEGIN), text.index(END) + len(END)
    tmp = doc.with_suffix(".tmp")
    tmp.write_text(text[:start] + region + text[end:], encoding="utf-8")
    tmp.replace(doc)


def run_tradeoffs(build_dir):
    """Runs every tradeoff study into docs/perf/*.csv and redraws docs/img/tradeoff-*.png."""
    run([sys.executable, str(ROOT / "scripts" / "plot_tradeoffs.py"), str(build_dir), "--run"], cwd=ROOT)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default=str(ROOT / "build-perf"), help="build folder (Release)")
    ap.add_argument("--no-build", action="store_true", help="use the build folder as it is")
    ap.add_argument("--quick", action="store_true",
                    help="smoke sizes, one repetition; results in BUILD/perf-quick/, docs untouched")
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--processes", type=int, default=1,
                    help="share the repetitions among this many processes, one after the other")
    ap.add_argument("--filter", default="", help="Google Benchmark filter (regex)")
    ap.add_argument("--json", help="make the results from this saved JSON instead of running")
    ap.add_argument("--no-tradeoffs", action="store_true", help="skip the tradeoff studies")
    args = ap.parse_args()
    build_dir = Path(args.build)
    if args.json:
        data = json.loads(Path(args.json).read_text())
    else:
        if not args.no_build:
            build(build_dir)
        out = build_dir / "bench.json"
        run_bench(build_dir, args.quick, args.repetitions, args.filter, out, args.processes)
        data = json.loads(out.read_text())
        print(f"wrote {out}")
    results = Results(data)
    rows = rows_of(results)
    if args.quick:
        quick = build_dir / "perf-quick"
        write_csv(rows, quick / "results.csv")
        (quick / "tables.md").write_text(region_text(results, rows) + "\n", encoding="utf-8")
        print(f"wrote {quick}/results.csv and tables.md (smoke numbers: not for docs/)")
        return 0
    write_csv(rows, CSV_PATH)
    write_doc(region_text(results, rows), DOC)
    print(f"wrote {CSV_PATH} and the tables of {DOC}")
    if not args.json and not args.no_tradeoffs:
        run_tradeoffs(build_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
