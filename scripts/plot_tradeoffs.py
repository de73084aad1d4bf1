#!/usr/bin/env python3
"""Run time against error: CSVs from bench/tradeoff and their Pareto plots.

Usage:
  scripts/plot_tradeoffs.py [BUILD_DIR] [--run] [--quick] [--csv-dir DIR] [--img-dir DIR]
                            [--ccd-default MODE@HZ]
      Plots docs/perf/{integrators,precision,ccd}.csv (the ones present) into
      docs/img/tradeoff-*.png. With --run it first runs BUILD_DIR/bench/cardemo_tradeoff_NAME
      (BUILD_DIR defaults to build/) for every study it finds there and writes the CSVs.
      --quick runs the harnesses' --quick mode and writes into BUILD_DIR/tradeoff-quick/ instead
      of docs/ (quick numbers are for smoke tests, not for the docs).
  scripts/plot_tradeoffs.py --check STUDY CSV
      Checks that CSV parses as STUDY's table (integrators, precision or ccd); no matplotlib.
  scripts/plot_tradeoffs.py --smoke STUDY EXECUTABLE OUT_CSV
      Runs `EXECUTABLE --quick --csv OUT_CSV`, then --check (the CTest smoke test).

The Pareto front is the set of points that no other point beats on both axes (cost and error,
lower is better for both); it is drawn as a staircase. The product's default is ringed in red.
"""
import argparse
import csv
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from pyplot_loader import import_pyplot  # noqa: E402
ROOT = os.path.dirname(HERE)

# Column schemas: name -> type (str, int, float). Every column must be present, in this order.
SCHEMAS = {
    "integrators": [("case", str), ("scheme", str), ("hz", int), ("seconds", float),
                    ("steps", int), ("final_err_m", float), ("max_err_m", float),
                    ("ns_per_step", float), ("ns_per_sim_s", float), ("is_default", int)],
    "precision": [("kernel", str), ("boxes", str), ("offset_m", float), ("pairs", int),
                  ("borderline", int), ("hit_wrong", int), ("sep_bad", int),
                  ("misclassified", int), ("misclassified_rate", float),
                  ("sep_err_max_m", float), ("same_bits_as_product", int),
                  ("ns_per_pair", float), ("is_default", int)],
    "ccd": [("mode", str), ("hz", int), ("speed_mps", float), ("cases", int), ("missed", int),
            ("toi_err_mean_s", float), ("toi_err_max_s", float), ("ns_per_step", float)],
}
STUDIES = ["integrators", "precision", "ccd"]
# Errors of exactly 0 cannot sit on a log axis: they are drawn at this floor (noted on the plot).
ZERO_FLOOR = 1e-16
# Integrator errors below this are the rounding of hundreds of double additions on positions of
# tens of metres (ulp(50 m) = 7e-15 m), not the scheme's; the plots shade that band.
ROUNDING = 1e-12


class CsvError(Exception):
    pass


def read_table(study, path):
    """Rows of a study's CSV as dicts of typed values; raises CsvError naming file and line."""
    schema = SCHEMAS[study]
    with open(path, newline="") as f:
        reader = csv.reader(f)
        try:
            header = next(reader)
        except StopIteration:
            raise CsvError(f"{path}:1: empty file")
        expected = [name for name, _ in schema]
        # A study may append columns; the contract columns must come first, in order.
        if header[:len(expected)] != expected:
            raise CsvError(f"{path}:1: header {header} does not start with {expected}")
        rows = []
        for line, fields in enumerate(reader, start=2):
            if len(fields) != len(header):
                raise CsvError(f"{path}:{line}: {len(fields)} fields, expected {len(header)}")
            row = {}
            for (name, kind), text in zip(schema, fields):
                if study == "ccd" and name.startswith("toi_err") and text == "":
                    row[name] = None  # every case tunnelled: no contact time to compare
                    continue
                try:
                    value = kind(text)
                except ValueError:
                    raise CsvError(f"{path}:{line}: {name}: '{text}' is not {kind.__name__}")
                if kind is not str and (not math.isfinite(value) or value < 0):
                    raise CsvError(f"{path}:{line}: {name}: {text} is not finite and >= 0")
                row[name] = value
            rows.append(row)
    if not rows:
        raise CsvError(f"{path}:2: no data rows")
    return rows


def check_table(study, path):
    """Parses and checks the study's invariants; returns the rows."""
    rows = read_table(study, path)
    if study == "integrators":
        for case in {r["case"] for r in rows}:
            defaults = [r for r in rows if r["case"] == case and r["is_default"] == 1]
            if len(defaults) != 1:
                raise CsvError(f"{path}: case {case}: {len(defaults)} default rows, expected 1")
            for scheme in {r["scheme"] for r in rows}:
                rates = sorted(r["hz"] for r in rows if r["case"] == case and r["scheme"] == scheme)
                if len(rates) < 2 or len(set(rates)) != len(rates):
                    raise CsvError(f"{path}: case {case}, scheme {scheme}: rates {rates}")
        for r in rows:
            if r["max_err_m"] < r["final_err_m"] or r["ns_per_step"] <= 0:
                raise CsvError(f"{path}: {r['case']} {r['scheme']} {r['hz']} Hz: inconsistent row")
            # The fourth-order schemes land within nanometres of the closed forms; metres mean the
            # reference runs no longer describe the car being integrated (a new force in the game
            # that the run's closed form leaves out).
            if r["scheme"] in ("rk4", "arc_rk4") and not r["max_err_m"] < 1e-6:
                raise CsvError(f"{path}: {r['case']} {r['scheme']} {r['hz']} Hz: error "
                               f"{r['max_err_m']:.3g} m: the closed form does not match the car")
    elif study == "precision":
        if len({r["kernel"] for r in rows if r["is_default"] == 1}) != 1:
            raise CsvError(f"{path}: expected exactly one default kernel")
        for r in rows:
            counts = ("borderline", "hit_wrong", "sep_bad", "misclassified", "same_bits_as_product")
            if any(r[c] > r["pairs"] for c in counts) or r["pairs"] == 0:
                raise CsvError(f"{path}: {r['kernel']} at {r['offset_m']} m: counts exceed pairs")
            if abs(r["misclassified_rate"] - r["misclassified"] / r["pairs"]) > 1e-6:
                raise CsvError(f"{path}: {r['kernel']} at {r['offset_m']} m: rate mismatch")
            if r["is_default"] == 1 and r["same_bits_as_product"] != r["pairs"]:
                raise CsvError(f"{path}: the product differs from itself")
    elif study == "ccd":
        for r in rows:
            if r["missed"] > r["cases"]:
                raise CsvError(f"{path}: {r['mode']} {r['hz']} Hz: missed > cases")
            no_timing = r["toi_err_mean_s"] is None or r["toi_err_max_s"] is None
            if no_timing != (r["missed"] == r["cases"]):
                raise CsvError(f"{path}: {r['mode']} {r['hz']} Hz {r['speed_mps']} m/s: the error "
                               "fields are empty exactly when every case was missed")
    return rows


def mean(values):
    """Arithmetic mean; 0 for an empty list."""
    return sum(values) / len(values) if values else 0.0


def pareto(points):
    """Indices of the non-dominated points among (cost, error) pairs, sorted by cost."""
    front = []
    for i, (c, e) in enumerate(points):
        dominated = any((c2 <= c and e2 <= e) and (c2 < c or e2 < e)
                        for j, (c2, e2) in enumerate(points) if j != i)
        if not dominated:
            front.append(i)
    return sorted(front, key=lambda i: points[i])


def draw_front(ax, points, label="Pareto front"):
    front = pareto(points)
    xs = [points[i][0] for i in front]
    ys = [points[i][1] for i in front]
    ax.step(xs, ys, where="post", color="0.35", linestyle="--", linewidth=1.0, zorder=1,
            label=label)
    return front


DEFAULT_RING_SIZE = 260


def mark_default(ax, point, text):
    ax.scatter([point[0]], [point[1]], s=DEFAULT_RING_SIZE, facecolors="none", edgecolors="red",
               linewidths=2, zorder=5, label=text)


def legend(owner, *args, **kwargs):
    """owner.legend (an axes' or a figure's), with the default's ring drawn at a marker's size: at
    its plot size it covers the entry above it."""
    made = owner.legend(*args, **kwargs)
    handles = getattr(made, "legend_handles", None) or getattr(made, "legendHandles", [])
    for handle in handles:
        sizes = handle.get_sizes() if hasattr(handle, "get_sizes") else []
        if len(sizes) and sizes[0] == DEFAULT_RING_SIZE:
            handle.set_sizes([70])
    return made


def floor(e):
    return max(e, ZERO_FLOOR)


SCHEME_STYLE = {
    "semi_implicit_euler": ("semi-implicit Euler", "o", "tab:blue"),
    "explicit_euler": ("explicit Euler", "s", "tab:orange"),
    "rk4": ("RK4", "^", "tab:green"),
    "arc_rk4": ("exact arc + RK4 distance", "D", "tab:purple"),
}


def plot_integrators(plt, rows, out):
    cases = []
    for r in rows:
        if r["case"] not in cases:
            cases.append(r["case"])
    schemes = []
    for r in rows:
        if r["scheme"] not in schemes:
            schemes.append(r["scheme"])
    # The aggregate: worst max error over the runs against the mean cost, per (scheme, hz).
    keys = sorted({(r["scheme"], r["hz"]) for r in rows}, key=lambda k: (schemes.index(k[0]), k[1]))
    worst = []
    for scheme, hz in keys:
        cells = [r for r in rows if r["scheme"] == scheme and r["hz"] == hz]
        worst.append({"case": "worst of the four runs", "scheme": scheme, "hz": hz,
                      "max_err_m": max(r["max_err_m"] for r in cells),
                      "ns_per_sim_s": sum(r["ns_per_sim_s"] for r in cells) / len(cells),
                      "is_default": cells[0]["is_default"]})
    panels = cases + ["worst of the four runs"]
    cols = 3
    nrows = (len(panels) + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(5.2 * cols, 4.3 * nrows), dpi=110)
    axes = axes.flatten()
    summary = []
    for ax, case in zip(axes, panels):
        cells = worst if case == panels[-1] else [r for r in rows if r["case"] == case]
        points = [(r["ns_per_sim_s"], floor(r["max_err_m"])) for r in cells]
        front = draw_front(ax, points)
        for index, scheme in enumerate(schemes):
            label, marker, colour = SCHEME_STYLE.get(scheme, (scheme, "x", None))
            # Schemes take turns labelling above and below their points: pairs of schemes often
            # share a point (the two Eulers; RK4 and the arc on straight runs).
            label_offset = (4, 3) if index % 2 == 0 else (4, -9)
            sc = sorted((r for r in cells if r["scheme"] == scheme), key=lambda r: r["hz"])
            ax.plot([r["ns_per_sim_s"] for r in sc], [floor(r["max_err_m"]) for r in sc],
                    marker=marker, color=colour, label=label, linewidth=1, markersize=5)
            for r in sc:
                ax.annotate(f"{r['hz']}", (r["ns_per_sim_s"], floor(r["max_err_m"])),
                            textcoords="offset points", xytext=label_offset, fontsize=6,
                            color=colour)
        d = [i for i, r in enumerate(cells) if r["is_default"] == 1]
        if d:
            r = cells[d[0]]
            name = SCHEME_STYLE.get(r["scheme"], (r["scheme"],))[0]
            mark_default(ax, points[d[0]], f"default: {name}, {r['hz']} Hz")
            summary.append((case, d[0] in front))
        ax.axhspan(ZERO_FLOOR, ROUNDING, color="0.92", zorder=0)
        ax.text(0.02, 0.03, "double rounding over the run", transform=ax.transAxes, fontsize=6,
                color="0.45")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(ZERO_FLOOR, 3.0)
        ax.set_title(case.replace("_", " "), fontsize=10)
        ax.set_xlabel("CPU ns per simulated second (ns/step x hz)", fontsize=8)
        ax.set_ylabel("max position error over the run, m", fontsize=8)
        ax.grid(True, which="major", alpha=0.3)
        ax.tick_params(labelsize=7)
    for ax in axes[len(panels):]:
        ax.axis("off")
    handles, labels = axes[0].get_legend_handles_labels()
    legend(fig, handles, labels, loc="lower right", fontsize=8, bbox_to_anchor=(0.98, 0.08))
    fig.suptitle("Car integrators: error against closed forms vs cost (numbers by points: hz)",
                 fontsize=11)
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)
    return summary


KERNEL_STYLE = {
    "f32_world": ("f32 world coordinates", "o", "tab:red"),
    "f32_relative": ("f32 relative to the query", "s", "tab:orange"),
    "mixed": ("mixed (double offsets, float radii)", "^", "tab:green"),
    "f64_kernel": ("f64, bench kernel", "v", "tab:purple"),
    "f64": ("f64, product collideObb2", "D", "tab:blue"),
}


def plain_log_ticks(ax, values):
    """Readable ticks on a log x axis spanning less than a decade or two."""
    from matplotlib.ticker import FixedLocator, NullLocator
    lo, hi = min(values), max(values)
    candidates = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 15, 20, 25, 30, 40, 50, 70, 100, 150, 200,
                  300, 500, 1000]
    ticks = [t for t in candidates if lo / 1.15 <= t <= hi * 1.15]
    ax.xaxis.set_major_locator(FixedLocator(ticks))
    ax.xaxis.set_minor_locator(NullLocator())
    ax.set_xticklabels([f"{t:g}" for t in ticks])


def plot_precision(plt, rows, out):
    kernels = []
    for r in rows:
        if r["kernel"] not in kernels:
            kernels.append(r["kernel"])
    classes = []
    for r in rows:
        if r["boxes"] not in classes:
            classes.append(r["boxes"])
    offsets = sorted({r["offset_m"] for r in rows})
    min_pairs = min(r["pairs"] for r in rows)
    zero = 0.5 / min_pairs  # a rate of 0 is drawn here
    fig, axes = plt.subplots(len(classes), 2, figsize=(13, 4.4 * len(classes)), dpi=110,
                             squeeze=False)
    summary = []
    for (left, right), cls in zip(axes, classes):
        for kernel in kernels:
            label, marker, colour = KERNEL_STYLE.get(kernel, (kernel, "x", None))
            cells = sorted((r for r in rows if r["kernel"] == kernel and r["boxes"] == cls),
                           key=lambda r: r["offset_m"])
            left.plot(range(len(cells)), [max(r["misclassified_rate"], zero) for r in cells],
                      marker=marker, color=colour, markersize=5, label=label,
                      linestyle="--" if kernel == "f64_kernel" else "-")
        left.set_xticks(range(len(offsets)))
        left.set_xticklabels(["0" if o == 0 else f"1e{round(math.log10(o))}" for o in offsets])
        left.set_yscale("log")
        left.set_ylim(zero / 2, 2.0)
        left.text(0, zero * 1.25, f"none wrong (0 of {min_pairs:,} pairs)", fontsize=7,
                  color="0.4")
        left.set_xlabel("distance of the pair from the world origin, m")
        left.set_ylabel("misclassified: wrong verdict\nor |sep error| > 2e-6 m", fontsize=9)
        left.set_title(f"{cls} boxes: error against world offset", fontsize=10)
        left.grid(True, alpha=0.3)
        legend(left, fontsize=7, loc="center right")

        # Pareto: worst rate over the offsets against the median cost per pair.
        points, names = [], []
        for kernel in kernels:
            cells = [r for r in rows if r["kernel"] == kernel and r["boxes"] == cls]
            costs = sorted(r["ns_per_pair"] for r in cells)
            worst = max(r["misclassified_rate"] for r in cells)
            points.append((costs[len(costs) // 2], max(worst, zero)))
            names.append(kernel)
        front = draw_front(right, points)
        for (c, e), kernel in zip(points, names):
            label, marker, colour = KERNEL_STYLE.get(kernel, (kernel, "x", None))
            right.scatter([c], [e], marker=marker, color=colour, s=50, label=label, zorder=3)
        default = [i for i, k in enumerate(names)
                   if any(r["is_default"] == 1 for r in rows if r["kernel"] == k)]
        if default:
            mark_default(right, points[default[0]], "default (the product)")
            summary.append((f"precision, {cls} boxes", default[0] in front))
        right.set_xscale("log")
        right.set_yscale("log")
        right.set_ylim(zero / 2, 2.0)
        plain_log_ticks(right, [p[0] for p in points])
        right.set_xlabel("CPU ns per pair query (median over the offsets)")
        right.set_ylabel("worst misclassified rate over the offsets", fontsize=9)
        right.set_title(f"{cls} boxes: cost against the worst error", fontsize=10)
        right.grid(True, which="both", alpha=0.3)
        legend(right, fontsize=7, loc="center right")
    fig.suptitle("2D OBB SAT precision: pairs within 1e-7..1 m of touching, against the GMP oracle",
                 fontsize=11)
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)
    return summary


def plot_ccd(plt, rows, out, default):
    keys = []
    for r in rows:
        if (r["mode"], r["hz"]) not in keys:
            keys.append((r["mode"], r["hz"]))
    # Below the fast-motion bound every mode takes the same discrete path: the same misses and
    # errors, and costs that differ by noise only. Those speeds are left out of every mean.
    def outcome(r):
        return (r["cases"], r["missed"], r["toi_err_mean_s"], r["toi_err_max_s"])
    identical = set()
    for hz, speed in {(r["hz"], r["speed_mps"]) for r in rows}:
        group = [r for r in rows if r["hz"] == hz and r["speed_mps"] == speed]
        if len({outcome(r) for r in group}) == 1:
            identical.add((hz, speed))
    agg = []
    for mode, hz in keys:
        cells = [r for r in rows if r["mode"] == mode and r["hz"] == hz
                 and (hz, r["speed_mps"]) not in identical]
        if not cells:
            cells = [r for r in rows if r["mode"] == mode and r["hz"] == hz]
        cases = sum(r["cases"] for r in cells)
        agg.append({"mode": mode, "hz": hz,
                    "miss_rate": sum(r["missed"] for r in cells) / cases if cases else 0.0,
                    # Mean over the speeds of each row's mean error (hits found only; misses are
                    # the other panel). The max is no use here: below the fast-motion bound every
                    # mode reports contact at the frame's end, so every mode's max is one step.
                    "toi_mean": mean([r["toi_err_mean_s"] for r in cells
                                      if r["toi_err_mean_s"] is not None]),
                    "cost": hz * sum(r["ns_per_step"] for r in cells) / len(cells),
                    "cases": cases})
    modes = []
    for a in agg:
        if a["mode"] not in modes:
            modes.append(a["mode"])
    min_cases = max(1, min(a["cases"] for a in agg))
    zero_rate = 0.5 / min_cases
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.6), dpi=110)
    summary = []
    for ax, key, ylabel, zero in [
            (axes[0], "miss_rate", "missed impacts / cases (speeds where modes differ)", zero_rate),
            (axes[1], "toi_mean", "mean time-of-impact error, s (mean over those speeds)",
             ZERO_FLOOR)]:
        points = [(a["cost"], max(a[key], zero)) for a in agg]
        front = draw_front(ax, points)
        for i, mode in enumerate(modes):
            cells = sorted((j for j, a in enumerate(agg) if a["mode"] == mode),
                           key=lambda j: agg[j]["hz"])
            ax.plot([points[j][0] for j in cells], [points[j][1] for j in cells], marker="os^Dv"[i % 5],
                    label=mode, linewidth=1)
            for j in cells:
                ax.annotate(f"{agg[j]['hz']}", points[j], textcoords="offset points",
                            xytext=(4, 3), fontsize=6)
        d = [j for j, a in enumerate(agg) if f"{a['mode']}@{a['hz']}" == default]
        if d:
            mark_default(ax, points[d[0]], f"default: {default.replace('@', ', ')} Hz")
            # The step rate is the integrator study's choice; this study chooses the mode, so the
            # default is judged against the other modes at its rate.
            same_rate = [j for j, a in enumerate(agg) if a["hz"] == agg[d[0]]["hz"]]
            front_at_rate = [same_rate[i] for i in pareto([points[j] for j in same_rate])]
            summary.append((f"ccd {key}, modes at {agg[d[0]]['hz']} Hz", d[0] in front_at_rate))
        ax.set_xscale("log")
        ax.set_yscale("log")
        if key == "miss_rate":
            ax.axhline(zero, color="0.6", linewidth=0.8)
            ax.text(0.02, 0.02, f"on the grey line: none missed (0 of {min_cases:,})",
                    transform=ax.transAxes, fontsize=7, color="0.4")
        ax.set_xlabel("CPU ns per simulated second\n(ns/step x hz, mean over speeds where the "
                      "modes differ)", fontsize=9)
        ax.set_ylabel(ylabel, fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        legend(ax, fontsize=7)
    fig.suptitle("Continuous collision: misses and time-of-impact error vs cost (points: hz)",
                 fontsize=11)
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)
    return summary


def run_study(executable, csv_path, quick):
    cmd = [executable, "--csv", csv_path] + (["--quick"] if quick else [])
    print("running", " ".join(cmd), flush=True)
    r = subprocess.run(cmd)
    if r.returncode != 0:
        sys.exit(f"{executable} failed with exit status {r.returncode}")


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter,
                                 usage=argparse.SUPPRESS)
    ap.add_argument("build", nargs="?", default=os.path.join(ROOT, "build"))
    ap.add_argument("--run", action="store_true")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--csv-dir")
    ap.add_argument("--img-dir")
    ap.add_argument("--ccd-default", default="continuous@120")
    ap.add_argument("--check", nargs=2, metavar=("STUDY", "CSV"))
    ap.add_argument("--smoke", nargs=3, metavar=("STUDY", "EXECUTABLE", "OUT_CSV"))
    args = ap.parse_args(argv)
    for mode in (args.check, args.smoke):
        if mode and mode[0] not in SCHEMAS:
            ap.error(f"STUDY must be one of {', '.join(STUDIES)}")
    if args.check:
        study, table = args.check
        try:
            rows = check_table(study, table)
        except (CsvError, OSError) as e:
            print(e, file=sys.stderr)
            sys.exit(1)
        print(f"{table}: {len(rows)} rows, {study} table OK")
        return
    if args.smoke:
        study, executable, out_csv = args.smoke
        run_study(executable, out_csv, quick=True)
        main(["--check", study, out_csv])
        return

    build, run, quick = args.build, args.run, args.quick
    csv_dir, img_dir, ccd_default = args.csv_dir, args.img_dir, args.ccd_default
    if quick and not run:
        ap.error("--quick only makes sense with --run")
    scratch = os.path.join(build, "tradeoff-quick")
    csv_dir = csv_dir or (scratch if quick else os.path.join(ROOT, "docs", "perf"))
    img_dir = img_dir or (scratch if quick else os.path.join(ROOT, "docs", "img"))
    os.makedirs(csv_dir, exist_ok=True)
    os.makedirs(img_dir, exist_ok=True)
    # Before any run: this may restart the script under Debian's python3.
    plt = import_pyplot(__file__, argv)

    if run:
        for study in STUDIES:
            exe = os.path.join(build, "bench", f"cardemo_tradeoff_{study}")
            if os.path.exists(exe):
                run_study(exe, os.path.join(csv_dir, f"{study}.csv"), quick)
            else:
                print(f"skipping {study}: {exe} is not built")

    summary = []
    for study in STUDIES:
        path = os.path.join(csv_dir, f"{study}.csv")
        if not os.path.exists(path):
            continue
        try:
            rows = check_table(study, path)
        except CsvError as e:
            sys.exit(str(e))
        out = os.path.join(img_dir, f"tradeoff-{study}.png")
        if study == "integrators":
            summary += plot_integrators(plt, rows, out)
        elif study == "precision":
            summary += plot_precision(plt, rows, out)
        else:
            summary += plot_ccd(plt, rows, out, ccd_default)
        print(out)
    for panel, on_front in summary:
        print(f"default on the Pareto front: {'yes' if on_front else 'NO '}  {panel}")


if __name__ == "__main__":
    main(sys.argv[1:])
