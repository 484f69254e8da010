#!/usr/bin/env python3
"""Prints nbscope_bench's JSON output as a table: time per element, threads, bytes per element (own
arrays) and bytes moved per element (nbs's packed layout), and, under each BM_Check row, the check's
time by part; then the ratios of issues 12 and 26 from the one run, each target marked met or missed."""
import json
import sys

# BM_Check's counters, in the order of the check (bench/bench_check.cpp).
CHECK_PARTS = ["R_ms", "F_ms", "G/T_ms", "A==R_ms", "A-in-F_ms", "T-in-A_ms", "AABB-in-cells_ms"]


def main(path: str) -> None:
    with open(path) as f:
        data = json.load(f)
    rows = [b for b in data["benchmarks"] if b.get("run_type", "iteration") == "iteration"]
    print(f"{'benchmark':<48} {'ms/frame':>10} {'ns/elem':>9} {'threads':>7} {'B/elem':>8} {'moved B/el':>10} {'pairs':>10}")
    for b in rows:
        ms = b["real_time"] if b.get("time_unit") == "ms" else b["real_time"] / 1e6
        threads = f"{int(b['threads'])}" if "threads" in b else ""
        moved = f"{b['moved_bytes_per_element']:.0f}" if "moved_bytes_per_element" in b else ""
        print(f"{b['name']:<48} {ms:>10.3f} {ns_per_element(b):>9.1f} {threads:>7} "
              f"{b.get('bytes_per_element', 0):>8.1f} {moved:>10} {int(b.get('pairs', 0)):>10}")
        # BM_Check: the check's parts (ms of the last frame checked), on the line below.
        parts = [(k[:-3], b[k]) for k in CHECK_PARTS if k in b]
        if parts:
            print("    " + ", ".join(f"{name} {value:.3f}" for name, value in parts))
    # Tracing off vs no trace hooks at all, measured in this run: ~1.00 means it costs nothing.
    by_name = {b["name"]: b for b in rows}
    for name, b in by_name.items():
        if name.startswith("BM_TraceOff/nbs/"):
            plain = by_name.get(name.replace("BM_TraceOff/nbs/", "BM_TraceOff/nbs_plain/"))
            if plain:
                print(f"trace off / no hooks, {name[len('BM_TraceOff/nbs/'):]}: "
                      f"{b['real_time'] / plain['real_time']:.3f}")
    print_nbs_ratios(by_name)
    print_issue26_targets(by_name)


def ns_per_element(b: dict) -> float:
    """The ns_per_element counter, which Google Benchmark stores as seconds per element (an inverted rate)."""
    return b.get("ns_per_element", 0) * 1e9


def ns(by_name: dict, name: str):
    b = by_name.get(name)
    return ns_per_element(b) if b else None


def print_nbs_ratios(by_name: dict) -> None:
    """The ratios issue 12 asks for, each from this one run (rows missing from a filtered run are skipped)."""
    lines = []
    for dim in ("", "3d"):
        for layout in ("loose", "dense", "clustered"):
            small, large = ns(by_name, f"BM_Detect/nbs{dim}/{layout}/10000"), ns(by_name, f"BM_Detect/nbs{dim}/{layout}/1000000")
            if small and large:
                lines.append(f"nbs{dim} {layout}: ns/elem at 1e6 / at 1e4 = {large / small:.2f}")
            for n in ("10000", "100000", "1000000"):
                fast, book = ns(by_name, f"BM_Detect/nbs{dim}/{layout}/{n}"), ns(by_name, f"BM_Detect/nbs_book{dim}/{layout}/{n}")
                if fast and book:
                    lines.append(f"nbs{dim} {layout}/{n}: book loops / fast path = {book / fast:.2f}")
            if dim:
                for n in ("10000", "100000", "1000000"):
                    fast, sort = ns(by_name, f"BM_Detect/nbs3d/{layout}/{n}"), ns(by_name, f"BM_Detect/sort3d/{layout}/{n}")
                    if fast and sort:
                        lines.append(f"nbs3d {layout}/{n}: sort3d / nbs3d = {sort / fast:.2f}")
    fast = ns(by_name, "BM_Detect/nbs/loose/100000")
    for motion in ("small", "large"):
        box2d = ns(by_name, f"BM_Box2DBroadphase/loose/100000/{motion}")
        if fast and box2d:
            lines.append(f"loose/100000: Box2D broadphase ({motion} motion) / nbs from scratch = {box2d / fast:.2f}")
    for line in lines:
        print(line)


def verdict(value: float, target: float) -> str:
    return "met" if value <= target else "missed"


def print_issue26_targets(by_name: dict) -> None:
    """Issue 26's targets, each from this run (skipped when a filtered run lacks its rows): wall ns per
    element at 1e6, linearity 1e4 -> 1e7, nbs at 1e5 against Box2D's incremental update."""
    lines = []
    # (name without the threads suffix, threads, target ns/elem at 1e6)
    speed = [("nbs/loose", 1, 25), ("nbs/loose", 2, 15), ("nbs/dense", 1, 40), ("nbs/dense", 2, 25),
             ("nbs3d/loose", 1, 60), ("nbs3d/dense", 1, 150)]
    for stem, threads, target in speed:
        value = ns(by_name, f"BM_Detect/{stem}/1000000{suffix(threads)}")
        if value:
            lines.append(f"{stem}/1000000 on {threads} thread{'s' if threads > 1 else ''}: "
                         f"{value:.1f} ns/elem, target <= {target}: {verdict(value, target)}")
    for stem in ("nbs/loose", "nbs/dense", "nbs3d/loose", "nbs3d/dense"):
        for threads in (1, 2):
            small = ns(by_name, f"BM_Detect/{stem}/10000{suffix(threads)}")
            large = ns(by_name, f"BM_Detect/{stem}/10000000{suffix(threads)}")
            if small and large:
                lines.append(f"{stem} on {threads} thread{'s' if threads > 1 else ''}: ns/elem at 1e7 / at 1e4 = "
                             f"{large / small:.2f}, target <= 1.5: {verdict(large / small, 1.5)}")
    box2d = ns(by_name, "BM_Box2DBroadphase/loose/100000/small")
    for threads in (1, 2):
        fast = ns(by_name, f"BM_Detect/nbs/loose/100000{suffix(threads)}")
        if fast and box2d:
            lines.append(f"nbs/loose/100000 on {threads} thread{'s' if threads > 1 else ''} / Box2D incremental "
                         f"update = {fast / box2d:.2f}, target <= 1.5: {verdict(fast / box2d, 1.5)}")
    if lines:
        print("issue 26 targets:")
        for line in lines:
            print("  " + line)


def suffix(threads: int) -> str:
    """The benchmark name's threads part: none for 1 thread, /tT otherwise (bench/bench_detect.cpp)."""
    return "" if threads == 1 else f"/t{threads}"


if __name__ == "__main__":
    main(sys.argv[1])
