#!/usr/bin/env python3
"""How well the confirmed tracks know their targets' velocity, by time since the target's last
turn: the velocity sigma the tracks report next to their actual velocity error, and the
probability they give the mode named `cv`. Reads simulator truth and track streams (JSON Lines,
CONTRACTS.md) in pairs.

A target is turning between two truth frames when its heading changes faster than 0.02 rad/s.
Each confirmed track is matched to the nearest target within 2 km (eval's cutoff on the
racetrack) at the truth frame nearest its own time. Velocity errors and sigmas are per
horizontal axis: |v - v_true| / sqrt(2) and sqrt((P_vx + P_vy) / 2).

Usage: velocity-by-turn.py TRUTH TRACKS [TRUTH TRACKS ...]
"""
import json
import math
import sys
from collections import defaultdict

TURNING = 0.02  # [rad/s]
MATCH = 2000.0  # [m]
BINS = [(0.0, "in a turn"), (6.0, "0-6 s after"), (12.0, "6-12 s after"), (18.0, "12-18 s after"),
        (30.0, "18-30 s after"), (math.inf, "30 s or more")]


def read_truth(path):
    frames = {}
    for line in open(path):
        d = json.loads(line)
        frames[d["time"]] = {o["id"]: (o["position"], o["velocity"]) for o in d["objects"]}
    times = sorted(frames)
    since = {}  # (time, id) -> seconds since the target last turned (<= 0: turning)
    last_turn = defaultdict(lambda: -math.inf)
    for a, b in zip(times, times[1:]):
        for i, (_, v) in frames[b].items():
            if i not in frames[a]:
                continue
            u = frames[a][i][1]
            turn = math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])
            if abs(turn) / (b - a) > TURNING:
                last_turn[i] = b
            since[(b, i)] = b - last_turn[i]
    return frames, times, since


def main(paths):
    rows = defaultdict(lambda: [0, 0.0, 0.0, 0.0, 0])  # n, sum sigma, sum err^2, sum P(cv), n cv
    for truth_path, tracks_path in zip(paths[::2], paths[1::2]):
        frames, times, since = read_truth(truth_path)
        for line in open(tracks_path):
            d = json.loads(line)
            t = min(times, key=lambda x: abs(x - d["time"]))
            for k in d["tracks"]:
                if k["status"] != "confirmed":
                    continue
                p = k["position"]
                best = min(((math.hypot(p[0] - tp[0], p[1] - tp[1]), i, tv)
                            for i, (tp, tv) in frames[t].items()), default=None)
                if best is None or best[0] > MATCH or (t, best[1]) not in since:
                    continue
                s = since[(t, best[1])]
                label = next(name for edge, name in BINS if s <= edge)
                c, n = k["covariance"], int(math.isqrt(len(k["covariance"])))
                v, tv = k["velocity"], best[2]
                row = rows[label]
                row[0] += 1
                row[1] += math.sqrt((c[1 * n + 1] + c[3 * n + 3]) / 2)
                row[2] += ((v[0] - tv[0]) ** 2 + (v[1] - tv[1]) ** 2) / 2
                if "cv" in k.get("modes", {}):
                    row[3] += k["modes"]["cv"]
                    row[4] += 1
    print("| target | confirmed track-frames | reported velocity sigma (mean) | actual RMS velocity "
          "error | mean P(cv) |")
    print("|---|---|---|---|---|")
    for _, label in BINS:
        n, sigma, err2, cv, ncv = rows[label]
        if n:
            p_cv = f"{cv / ncv:.2f}" if ncv else "-"
            print(f"| {label} | {n} | {sigma / n:.1f} m/s | {math.sqrt(err2 / n):.1f} m/s | {p_cv} |")


if __name__ == "__main__":
    if len(sys.argv) < 3 or len(sys.argv) % 2 == 0:
        sys.exit(__doc__)
    main(sys.argv[1:])
