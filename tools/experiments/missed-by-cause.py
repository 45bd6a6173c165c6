#!/usr/bin/env python3
"""Missed targets per scan of a snapshot radar load, split by what explains them: beyond the
radar's range; not yet detected M times within N looks, plus the one look the existence test
takes to confirm (the earliest an M-of-N initiator can report the target); and the rest
("later than that"), also counted scan by scan.

A target counts as tracked in a scan when a confirmed or coasting track lies within the cutoff
of its truth position, tracks and targets paired nearest first (as `skytrack eval` pairs them
within its cutoff). A target is detected in a scan when a plot lies within --detected (1 km)
of its truth position: a polar plot converted with the scan's platform position (azimuth
clockwise from north), a Cartesian one as it is.

Usage: missed-by-cause.py TRUTH TRACKS PLOTS [--range M] [--cutoff M] [--detected M] [--m M]
                          [--n N]
"""
import argparse
import json
import math
from collections import Counter, defaultdict



def dist(a, b):
    """Euclidean distance over the coordinates both have (a 2-D truth against a 3-D plot)."""
    n = min(len(a), len(b))
    return math.dist(a[:n], b[:n])


def read_frames(path, key):
    frames = {}
    for line in open(path):
        d = json.loads(line)
        frames[round(d["time"], 3)] = d[key] if key else d
    return frames


def plot_positions(scan):
    """The scan's plots as x, y, z (polar plots converted; a 2-D plot lies at the platform's
    height), and the platform's position."""
    p0 = scan.get("platform", {}).get("position", [0.0, 0.0, 0.0])
    out = []
    for p in scan["plots"]:
        if "range" in p:
            r, az, el = p["range"], p["azimuth"], p.get("elevation", 0.0)
            out.append((p0[0] + r * math.cos(el) * math.sin(az),
                        p0[1] + r * math.cos(el) * math.cos(az), p0[2] + r * math.sin(el)))
        else:
            out.append((p["x"], p["y"], p.get("z", p0[2])))
    return out, p0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("truth")
    ap.add_argument("tracks")
    ap.add_argument("plots")
    ap.add_argument("--range", type=float, default=150000.0, help="radar range [m]")
    ap.add_argument("--cutoff", type=float, default=2000.0, help="track-to-target distance [m]")
    ap.add_argument("--detected", type=float, default=1000.0, help="plot-to-target distance [m]")
    ap.add_argument("--m", type=int, default=3)
    ap.add_argument("--n", type=int, default=4)
    a = ap.parse_args()
    truth = {t: {o["id"]: o["position"] for o in objs} for t, objs in read_frames(a.truth, "objects").items()}
    tracks = read_frames(a.tracks, "tracks")
    scans = read_frames(a.plots, None)
    times = sorted(truth)
    detected, in_range = defaultdict(list), defaultdict(list)
    for t in times:
        plots, p0 = plot_positions(scans[t]) if t in scans else ([], [0.0, 0.0, 0.0])
        for i, p in truth[t].items():
            detected[i].append(any(dist(q, p) < a.detected for q in plots))
            in_range[i].append(dist(p, p0) <= a.range)
    earliest = {}  # the look after the M-th detection within N looks, plus one to confirm
    for i, d in detected.items():
        earliest[i] = math.inf
        for k in range(len(d)):
            if d[k] and sum(d[max(0, k - a.n + 1):k + 1]) >= a.m:
                earliest[i] = k + 2
                break
    causes, later = Counter(), Counter()
    for k, t in enumerate(times):
        firm = [x["position"] for x in tracks.get(t, []) if x["status"] in ("confirmed", "coasting")]
        pairs = sorted((dist(p, q), i, j) for i, p in truth[t].items()
                       for j, q in enumerate(firm) if dist(p, q) < a.cutoff)
        tracked, used = set(), set()
        for _, i, j in pairs:
            if i not in tracked and j not in used:
                tracked.add(i)
                used.add(j)
        for i in truth[t]:
            if i in tracked:
                continue
            if not in_range[i][k]:
                causes["beyond the radar's range"] += 1
            elif k < earliest[i]:
                causes[f"before an ideal {a.m}-of-{a.n} start and one look to confirm"] += 1
            else:
                causes["later than that"] += 1
                later[k] += 1
    n = len(times)
    print(f"{n} scans: missed {sum(causes.values()) / n:.2f} targets per scan")
    for cause, count in causes.items():
        print(f"  {cause}: {count / n:.2f}")
    print("  later than that, per scan: " + " ".join(str(later[k]) for k in range(n)))


if __name__ == "__main__":
    main()
