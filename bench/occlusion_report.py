#!/usr/bin/env python3
"""Scores tracking through occluders from `scbt eval --perturb occlude:...` outputs.

For each perturbation folder given (OUT/occlude_...), reads frames.csv (E_AL per frame) and the
occluder events the evaluation wrote beside each results file (<tracker>/<Seq>.occlusion.txt),
then prints per sequence: S@10 over all frames, during the events and over the 30 frames after
each, and the frames each event took to come back (the first frame after the occluder left from
which E_AL stays under 10 px for 5 frames; 'never' when it does not within the sequence).

    bench/occlusion_report.py OUT/occlude_0.3_2_bar_sweep_solid [more folders...]
"""
import csv
import math
import os
import sys
from collections import defaultdict

WRONG_PX = 10.0
AFTER = 30
HOLD = 5


def read_events(path):
    events = []
    with open(path) as f:
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            start, end, hidden = line.split()
            events.append((int(start), int(end), float(hidden)))
    return events


def back_delay(errors, end):
    """Frames from `end` (first frame after the event) until E_AL stays under WRONG_PX."""
    last = max(errors) if errors else 0
    for f in range(end, last + 1):
        window = [errors.get(g, math.inf) for g in range(f, f + HOLD) if g <= last]
        if window and all(e < WRONG_PX for e in window):
            return f - end
    return None


def report(folder):
    frames = defaultdict(dict)  # (tracker, seq) -> frame -> e_al
    with open(os.path.join(folder, "frames.csv")) as f:
        for row in csv.DictReader(f):
            e = float(row["e_al"]) if row["e_al"] not in ("", "inf") else math.inf
            frames[(row["tracker"], row["sequence"])][int(row["frame"])] = e
    pooled = defaultdict(lambda: [0, 0])
    delays_all = []
    print(f"## {os.path.basename(folder.rstrip('/'))}")
    print("| tracker | sequence | S@10 | S@10 during | S@10 after | events | back in <=10 | delays |")
    print("|---|---|---|---|---|---|---|---|")
    for (tracker, seq), errors in sorted(frames.items()):
        path = os.path.join(folder, tracker, seq + ".occlusion.txt")
        if not os.path.exists(path):
            continue
        events = read_events(path)
        during = [e for s, t, _ in events for f, e in errors.items() if s <= f < t]
        after = [e for s, t, _ in events for f, e in errors.items() if t <= f < t + AFTER]
        ok = lambda xs: sum(1 for x in xs if x < WRONG_PX)
        delays = [back_delay(errors, t) for _, t, _ in events]
        delays_all += delays
        back = sum(1 for d in delays if d is not None and d <= 10)
        for key, xs in (("all", list(errors.values())), ("during", during), ("after", after)):
            pooled[key][0] += ok(xs)
            pooled[key][1] += len(xs)
        rate = lambda xs: f"{ok(xs) / len(xs):.3f}" if xs else "-"
        shown = " ".join("never" if d is None else str(d) for d in delays)
        print(f"| {tracker} | {seq} | {rate(list(errors.values()))} | {rate(during)} | "
              f"{rate(after)} | {len(events)} | {back}/{len(events)} | {shown} |")
    p = {k: (v[0] / v[1] if v[1] else float("nan")) for k, v in pooled.items()}
    back = sum(1 for d in delays_all if d is not None and d <= 10)
    print(f"| all | pooled | {p.get('all', 0):.3f} | {p.get('during', 0):.3f} | "
          f"{p.get('after', 0):.3f} | {len(delays_all)} | {back}/{len(delays_all)} | |")
    print()


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for folder in sys.argv[1:]:
        report(folder)


if __name__ == "__main__":
    main()
