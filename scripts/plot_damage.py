#!/usr/bin/python3
"""The damage field of an MPM run as a PNG (issue 34; docs/mpm.md, "Damage").

    /usr/bin/python3 scripts/plot_damage.py OUTPUT_FOLDER [--frame K] [--out FILE]

Reads OUTPUT_FOLDER/result.json (written by `sinew solve` on an mpm scene
with "mpm_damage"), takes its last VTP frame (or frame K) and draws every
particle coloured by its damage d in [0, 1]. 3D runs are cut: the particles
within one grid spacing of the mid-plane across their thinnest extent.
The PNG goes to OUTPUT_FOLDER/damage.png unless --out says otherwise.
matplotlib and numpy are Debian's (scripts/setup.sh).
"""
import argparse
import base64
import json
import os
import struct
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

TYPES = {"Float64": "<f8", "Int64": "<i8", "UInt8": "u1"}


def data_array(element):
    """The values of one VTK DataArray (ascii, or binary: base64 of a UInt32
    byte count and the little-endian values), one row per tuple."""
    dtype = np.dtype(TYPES[element.get("type")])
    text = (element.text or "").strip()
    if element.get("format") == "binary":
        raw = base64.b64decode(text)
        (size,) = struct.unpack("<I", raw[:4])
        values = np.frombuffer(raw[4 : 4 + size], dtype=dtype)
    else:
        values = np.array(text.split(), dtype=dtype)
    components = int(element.get("NumberOfComponents", "1"))
    return values.reshape(-1, components)


def read_frame(path):
    """Positions (n × 3) and the point arrays by name of a VTP file."""
    piece = ET.parse(path).getroot().find("PolyData/Piece")
    points = data_array(piece.find("Points/DataArray"))
    arrays = {a.get("Name"): data_array(a) for a in piece.find("PointData")}
    return points, arrays


def fail(message):
    print("plot_damage: " + message, file=sys.stderr)
    sys.exit(2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder")
    parser.add_argument("--frame", type=int, help="frame index (default: the last)")
    parser.add_argument("--out", help="PNG path (default: FOLDER/damage.png)")
    args = parser.parse_args()
    try:
        with open(os.path.join(args.folder, "result.json")) as f:
            result = json.load(f)
    except (OSError, ValueError) as e:
        fail(f"{args.folder}/result.json: {e}")
    frames = result.get("vtp") or []
    if result.get("scene") != "mpm" or not frames:
        fail(f"{args.folder}/result.json: not an mpm run with VTP frames")
    index = len(frames) - 1 if args.frame is None else args.frame
    if not 0 <= index < len(frames):
        fail(f"--frame {index}: the run has frames 0 to {len(frames) - 1}")
    points, arrays = read_frame(os.path.join(args.folder, frames[index]))
    if "damage" not in arrays:
        fail(f"{frames[index]}: no damage array")
    d = arrays["damage"][:, 0]
    dx = float(result["dx"])
    if int(result["dimension"]) == 3:
        extent = points.max(axis=0) - points.min(axis=0)
        thin = int(np.argmin(extent))
        middle = 0.5 * (points[:, thin].max() + points[:, thin].min())
        keep = np.abs(points[:, thin] - middle) <= dx
        axes = [a for a in range(3) if a != thin]
        points, d = points[keep][:, axes], d[keep]
        title = f"damage, {'xyz'[thin]} = {middle:.3g} m ± dx"
    else:
        points = points[:, :2]
        title = "damage"
    time = result["frames"][index]["time"] if index < len(result.get("frames", [])) else float("nan")
    figure, axis = plt.subplots(figsize=(6, 6), dpi=150)
    # a marker of about the particles' spacing (dx/2 at 2 a cell) in points², the axes ~4.5 in wide
    size = (72.0 * 4.5 / max(np.ptp(points[:, 0]), np.ptp(points[:, 1]), dx) * dx / 2) ** 2
    cloud = axis.scatter(points[:, 0], points[:, 1], c=d, s=size, cmap="inferno", vmin=0.0, vmax=1.0, linewidths=0)
    axis.set_aspect("equal")
    axis.set_xlabel("m")
    axis.set_title(f"{os.path.basename(os.path.normpath(args.folder))}: {title} at t = {time:.3g} s")
    figure.colorbar(cloud, ax=axis, label="d", shrink=0.8)
    out = args.out or os.path.join(args.folder, "damage.png")
    figure.savefig(out, bbox_inches="tight")
    print(out)


if __name__ == "__main__":
    main()
