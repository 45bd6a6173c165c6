#!/usr/bin/env python3
"""A generated load scenario on stdout: N point targets at 150-300 m/s spread 20-140 km round
a snapshot 3-D radar (150 km, Pd 0.9) and C clutter plots per scan. Shared by track-load.sh
and display-load.sh.

Usage: load-scenario.py NAME TARGETS CLUTTER DURATION SCAN_PERIOD [SECTOR_DEG]
SECTOR_DEG (default 360) bunches the targets' bearings into [0, SECTOR_DEG) degrees.
"""
import math
import random
import sys

name, targets, clutter = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
duration, scan_period = sys.argv[4], sys.argv[5]
sector = math.radians(float(sys.argv[6])) if len(sys.argv) > 6 else 2 * math.pi
rng = random.Random(7)
print(f"""scenario: {{name: {name}, dimensions: 3, duration: {duration}, seed: 1}}
platform: {{position: [0, 0, 20]}}
sensor:
  scan_period: {scan_period}
  detection_probability: 0.9
  max_range: 150000
  sigma: {{range: 30.0, azimuth: 0.002, elevation: 0.003}}
clutter: {{mean: {clutter}, range: [5000, 150000], elevation: [0.0, 0.1]}}
targets:""")
for i in range(targets):
    r, b = 20000 + 120000 * rng.random(), sector * rng.random()
    h, v = 2 * math.pi * rng.random(), 150 + 150 * rng.random()
    print(f"  - {{id: {i}, position: [{r*math.sin(b):.1f}, {r*math.cos(b):.1f}, "
          f"{1000 + 9000*rng.random():.1f}], velocity: [{v*math.sin(h):.2f}, {v*math.cos(h):.2f}, 0]}}")
