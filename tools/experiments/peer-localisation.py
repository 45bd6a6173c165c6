#!/usr/bin/env python3
"""The peer benchmark's localisation against a Kalman filter that knows which plot is its
target's: for each run, the mean position error and NEES of skytrack's confirmed and coasting
tracks (each matched to the nearest target within 25 m, GOSPA's cutoff) next to those of the
benchmark's own filter (constant velocity, q = 0.5 m^2/s^3, sigma 5 m) fed each target's plot
when one lies within 15 m of it (3 sigma; otherwise a miss) and counted from its fourth scan,
where a 4-hit initiation reports it at the earliest. Reads the files of
compare-peer-benchmark.sh (CONTRACTS.md formats).

Usage: peer-localisation.py CELL_DIR TRACKER SEED [SEED ...]
  e.g. peer-localisation.py out/experiments/peer-benchmark/t5_c10 branching 1 2 3
"""
import json
import math
import sys

Q = 0.5  # [m^2/s^3]
R = 25.0  # [m^2]
MATCH = 25.0  # [m]
OWN_PLOT = 15.0  # [m]


def frames(path):
    return [json.loads(line) for line in open(path)]


def known_association(truth, plots):
    """(error, nees) per target and scan of the filter fed each target's own plot."""
    out = []
    for target in [o["id"] for o in truth[0]["objects"]]:
        axes, scans = None, 0
        for t_frame, p_frame in zip(truth, plots):
            obj = next((o for o in t_frame["objects"] if o["id"] == target), None)
            if obj is None:
                continue
            tx, ty = obj["position"][:2]
            own = [p for p in p_frame["plots"] if "x" in p and
                   math.hypot(p["x"] - tx, p["y"] - ty) < OWN_PLOT]
            z = (own[0]["x"], own[0]["y"]) if own else None
            if axes is None:
                if z is None:
                    continue
                axes = [[z[a], 0.0, R, 0.0, 1.0e4] for a in range(2)]  # x, v, Pxx, Pxv, Pvv
            else:
                for a in range(2):
                    x, v, pxx, pxv, pvv = axes[a]
                    x, pxx, pxv, pvv = x + v, pxx + 2 * pxv + pvv + Q / 3, pxv + pvv + Q / 2, pvv + Q
                    if z is not None:
                        s = pxx + R
                        kx, kv = pxx / s, pxv / s
                        y = z[a] - x
                        x, v = x + kx * y, v + kv * y
                        pxx, pxv, pvv = (1 - kx) * pxx, (1 - kx) * pxv, pvv - kv * pxv
                    axes[a] = [x, v, pxx, pxv, pvv]
            scans += 1
            if scans >= 4:
                dx, dy = axes[0][0] - tx, axes[1][0] - ty
                out.append((math.hypot(dx, dy), dx * dx / axes[0][2] + dy * dy / axes[1][2]))
    return out


def tracked(truth, tracks):
    """(error, nees) of each confirmed or coasting track matched to a target within 25 m."""
    at = {f["time"]: [o["position"][:2] for o in f["objects"]] for f in truth}
    out = []
    for frame in tracks:
        targets = at.get(frame["time"])
        if not targets:
            continue
        for track in frame["tracks"]:
            if track["status"] not in ("confirmed", "coasting"):
                continue
            px, py = track["position"][:2]
            tx, ty = min(targets, key=lambda p: (p[0] - px) ** 2 + (p[1] - py) ** 2)
            dx, dy = px - tx, py - ty
            if math.hypot(dx, dy) > MATCH:
                continue
            c, n = track["covariance"], math.isqrt(len(track["covariance"]))
            a, b, d = c[0], c[n // 2], c[(n // 2) * n + n // 2]  # x, y of [x vx y vy]
            det = a * d - b * b
            out.append((math.hypot(dx, dy), (d * dx * dx - 2 * b * dx * dy + a * dy * dy) / det))
    return out


def mean(pairs, i):
    return sum(p[i] for p in pairs) / len(pairs)


def main(cell, tracker, seeds):
    print("| seed | skytrack: mean error / NEES (pairs) | known association: mean error / NEES (pairs) |")
    print("|---|---|---|")
    ours_all, ideal_all = [], []
    for seed in seeds:
        base = f"{cell}/s{seed}"
        truth = frames(f"{base}.truth.jsonl")
        ours = tracked(truth, frames(f"{base}.{tracker}.tracks.jsonl"))
        ideal = known_association(truth, frames(f"{base}.plots.jsonl"))
        ours_all += ours
        ideal_all += ideal
        print(f"| {seed} | {mean(ours, 0):.2f} m / {mean(ours, 1):.2f} ({len(ours)}) | "
              f"{mean(ideal, 0):.2f} m / {mean(ideal, 1):.2f} ({len(ideal)}) |")
    print(f"| all | {mean(ours_all, 0):.2f} m / {mean(ours_all, 1):.2f} ({len(ours_all)}) | "
          f"{mean(ideal_all, 0):.2f} m / {mean(ideal_all, 1):.2f} ({len(ideal_all)}) |")


if __name__ == "__main__":
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2], sys.argv[3:])
