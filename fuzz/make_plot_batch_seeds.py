#!/usr/bin/env python3
"""Writes the seeds of the plot_batch fuzz target (fuzz/seeds/plot_batch/) in its input
layout (fuzz/plot_batch_fuzz_target.cpp): the plot streams of tests/tools/data as PlotBatch
samples, plus the malformed cases. Run from the repository root; the output is committed."""
import json
import math
import pathlib
import struct

ROOT = pathlib.Path(__file__).resolve().parent.parent
OUT = ROOT / "fuzz/seeds/plot_batch"
STRIDE = 17
TIME, RANGE, AZIMUTH, ELEVATION, RANGE_RATE, X, Y, Z = range(8)
SIGMA_RANGE = 10
CARTESIAN = 1 << 31


def i16(v):
    return struct.pack("<h", max(-32768, min(32767, int(round(v)))))


def scaled(k, value, batch_time):
    """The int16 that plot_value() scales back to `value` in slot k."""
    if k == TIME:
        return i16((value - batch_time) / 1e-3)
    if k == RANGE:
        return i16(value / 4.0 - 32768.0)
    if k == AZIMUTH:
        return i16(value / 1e-4)
    if k == ELEVATION:
        return i16(value / 2e-5)
    if k in (X, Y):
        return i16(value / 10.0)
    if k == Z:
        return i16(value)
    return i16(value / (1e-3 if k >= SIGMA_RANGE else 0.01))


def batch(line, previous, control_extra=0, mode3a=False, mode_s=False, flight_level=False):
    """One batch from a plot-stream line, scaled values; relative header when it follows."""
    scan = json.loads(line)
    control = control_extra | (0x20 if mode3a else 0) | (0x40 if mode_s else 0)
    control |= 0x80 if flight_level else 0
    out = b""
    if previous is not None and scan["sensor"] == previous["sensor"] and \
            scan["scan"] == previous["scan"] + 1:
        control |= 0x01
        out += bytes([int(round((scan["time"] - previous["time"]) / 0.25)) & 0xFF])
    else:
        out += struct.pack("<IQd", scan["sensor"], scan["scan"], scan["time"])
    if "platform" in scan:
        control |= 0x02
        p = scan["platform"]
        for key in ("position", "velocity", "attitude"):
            out += struct.pack("<3d", *(p.get(key, [0.0, 0.0, 0.0]) + [0.0] * 3)[:3])
    if "sigma" in scan:
        control |= 0x04
        names = ["range", "azimuth", "elevation", "range_rate", "x", "y", "z"]
        flags = sum(1 << i for i, n in enumerate(names) if n in scan["sigma"])
        out += struct.pack("<7dI", *[scan["sigma"].get(n, 0.0) for n in names], flags)
    plots = scan["plots"]
    out += bytes([len(plots)])
    for p in plots:
        values = [0.0] * STRIDE
        flags = 0
        slots = {"time": TIME, "range": RANGE, "azimuth": AZIMUTH, "elevation": ELEVATION,
                 "range_rate": RANGE_RATE, "x": X, "y": Y, "z": Z}
        for key, k in slots.items():
            if key in p:
                values[k] = p[key]
                flags |= 1 << k
        if "x" in p:
            flags |= CARTESIAN
        out += bytes([0]) + bytes([p["id"] & 0xFF]) + struct.pack("<I", flags)
        out += b"".join(scaled(k, v, scan["time"]) for k, v in enumerate(values))
    if mode3a:
        out += b"".join(struct.pack("<h", int(p.get("mode3a", "-1"), 8) if "mode3a" in p else -1)
                        for p in plots)
    if mode_s:
        out += b"".join(struct.pack("<i", int(p["mode_s"], 16) if "mode_s" in p else -1)
                        for p in plots)
    if flight_level:
        out += b"".join(i16(p.get("flight_level", math.nan) * 10) if "flight_level" in p
                        else i16(0) for p in plots)
    return bytes([control]) + out, scan


def stream(variant, lines, **options):
    out, previous = bytes([variant]), None
    for line in lines:
        data, previous = batch(line, previous, **options)
        out += data
    return out


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    data = ROOT / "tests/tools/data"
    identity = (data / "identity.plots.jsonl").read_text().splitlines()
    rotating = (data / "rotating.plots.jsonl").read_text().splitlines()
    # Four batches of three Cartesian targets with Mode 3/A codes, default profile.
    (OUT / "identity_cartesian").write_bytes(stream(0, identity[:4], mode3a=True))
    # A rotating antenna's polar plots with their own times, platform and sigmas.
    (OUT / "rotating_polar").write_bytes(stream(5, rotating))
    # docs/formats.md's plot-stream example, 3-D profile, with transponder values added.
    example = {"sensor": 1, "scan": 42, "time": 420.0,
               "platform": {"position": [0.0, 0.0, 8000.0], "velocity": [220.0, 0.0, 0.0],
                            "attitude": [0.10, 0.0, 0.0]},
               "sigma": {"range": 15.0, "azimuth": 0.002, "elevation": 0.004, "range_rate": 1.0},
               "plots": [{"id": 0, "range": 35120.5, "azimuth": 1.2034, "elevation": -0.21,
                          "range_rate": -180.2, "snr_db": 14.2, "mode_s": "4CA2D7",
                          "flight_level": 221},
                         {"id": 1, "x": 1200.0, "y": -340.0}]}
    later = dict(example, scan=43, time=424.0)
    (OUT / "formats_example_3d").write_bytes(
        stream(3, [json.dumps(example), json.dumps(later)], mode_s=True, flight_level=True))
    # Lengths that disagree (from_dds refuses the batch), then a consistent one (GNN).
    bad = bytes([0x10]) + struct.pack("<IQd", 1, 0, 0.0) + bytes([2, 3]) + \
        struct.pack("<H", 2 * STRIDE) + bytes([0, 0, 0])
    bad += (bytes([0, 0]) + struct.pack("<I", 0x60) + i16(100) * STRIDE) * 2
    bad += bytes([0]) + struct.pack("<I", 0x60)  # the third plot: flags only
    (OUT / "lengths_disagree").write_bytes(bytes([1]) + bad + batch(identity[0], None)[0])
    # Raw values: NaN, infinities, a huge finite range, a negative range (clutter rejection).
    raw = bytes([0]) + struct.pack("<IQd", 7, 3, 12.5) + bytes([4])
    for rng, az in ((math.nan, 0.1), (math.inf, 0.2), (1e300, 0.3), (-5.0, -math.inf)):
        values = [0.0] * STRIDE
        values[RANGE], values[AZIMUTH] = rng, az
        raw += bytes([1]) + struct.pack("<qI", 9, 0x6) + struct.pack(f"<{STRIDE}d", *values)
    (OUT / "raw_non_finite").write_bytes(bytes([2]) + raw)


if __name__ == "__main__":
    main()
