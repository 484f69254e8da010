#!/usr/bin/env python3
"""Prints nbscope_bench's JSON output as a table: time per element and bytes per element (and, under
each BM_Check row, the check's time by part)."""
import json
import sys

# BM_Check's counters, in the order of the check (bench/bench_check.cpp).
CHECK_PARTS = ["R_ms", "F_ms", "G/T_ms", "A==R_ms", "A-in-F_ms", "T-in-A_ms", "AABB-in-cells_ms"]


def main(path: str) -> None:
    with open(path) as f:
        data = json.load(f)
    rows = [b for b in data["benchmarks"] if b.get("run_type", "iteration") == "iteration"]
    print(f"{'benchmark':<48} {'ms/frame':>10} {'ns/elem':>9} {'B/elem':>8} {'pairs':>10}")
    for b in rows:
        ms = b["real_time"] if b.get("time_unit") == "ms" else b["real_time"] / 1e6
        # ns_per_element is an inverted rate (kIsIterationInvariantRate | kInvert): Google Benchmark
        # writes it in seconds per element.
        ns = b.get("ns_per_element", 0)
        ns = ns * 1e9 if ns < 1e-3 else ns
        print(f"{b['name']:<48} {ms:>10.3f} {ns:>9.1f} "
              f"{b.get('bytes_per_element', 0):>8.1f} {int(b.get('pairs', 0)):>10}")
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


if __name__ == "__main__":
    main(sys.argv[1])
