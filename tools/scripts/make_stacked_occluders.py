#!/usr/bin/env python3
"""Writes stacked_occluders.gltf (+ .bin): a probe for the light bleeding of the filterable
shadow maps (filter "vsm" and "evsm"), for engine-render --truth and the bench.

Variance shadow maps bleed where one filter window of the map holds two occluders at very
different depths and the receiver lies behind both: the mean then sits between the two
depths, the variance is large, and Chebyshev's bound lets light through although every ray
is blocked. So the probe stacks two occluders in light space:

  - a low slab B, 2.4 x 4 x 0.1, 0.8 to 0.9 above a 24 x 24 ground (top at y = 0);
  - a grate A high above it (5.0 to 5.05): 4 slats 0.2 wide and 3 long, 0.6 apart, placed
    so that from the lights it lies over B: the slats' shadows fall inside B's umbra on the
    ground, 0.25 apart.

Between two slats' shadows the map holds B's depth, beside them A's; the ground there is in
B's umbra either way (the truth: no light), and a blurred map lets light through in the
gaps (B's depth is near the receiver's, A's far in front: with a quarter of a window on A,
Chebyshev's bound is about 0.5). Eight slat edges make the bleeding a fair share of the
view. Both lights are low (their rays fall 1 unit per 3 across), so B's shadow lies beside
B, not under it, and the first camera sees the bleeding region directly.

Lights: "sun" (directional, one map: cascades 1, so its moments are one mipmappable 2D map)
and "spot" (its far plane fitted by the plugin: finite, as vsm and evsm need). Neither sets a
filter: the command line or the bench chooses (--light-set NAME.filter='"vsm"', --filters).
Cameras: "above" (the first, over the bleeding region) and "side".
Run: python3 tools/scripts/make_stacked_occluders.py OUT_DIR
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import GltfBuilder, normalize  # noqa: E402

# Rays fall 1 unit for every RUN units along -x: a point at height h shadows the ground
# RUN * h further toward -x.
RUN = 3.0
LOW = {"x": (0.0, 2.4), "z": (-2.0, 2.0), "y": (0.8, 0.9)}
# B's shadow on the ground: x in [0 - RUN * 0.9, 2.4 - RUN * 0.8] = [-2.7, 0].
GRATE_Y = (5.0, 5.05)
SLATS, SLAT_WIDTH, SLAT_PERIOD = 4, 0.2, 0.6
# Where the edge toward the lights (+x) of the last slat's shadow falls on the ground. A
# slat's shadow is SLAT_WIDTH + RUN * 0.05 = 0.35 wide, so the grate's covers
# [GRATE_EDGE_X - 3 * 0.6 - 0.35, GRATE_EDGE_X] = [-2.45, -0.3]: inside B's.
GRATE_EDGE_X = -0.3


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: python3 tools/scripts/make_stacked_occluders.py OUT_DIR")
    g = GltfBuilder()
    ground = g.material("ground", (0.7, 0.7, 0.7), roughness=0.9)
    low_material = g.material("low slab", (0.6, 0.45, 0.3), roughness=0.7)
    grate_material = g.material("grate", (0.3, 0.45, 0.6), roughness=0.7)
    g.box_node("ground", (-12.0, -0.5, -12.0), (12.0, 0.0, 12.0), ground)
    (x0, x1), (z0, z1), (y0, y1) = LOW["x"], LOW["z"], LOW["y"]
    g.box_node("low", (x0, y0, z0), (x1, y1, z1), low_material)
    # A slat's edge toward the lights (its bottom face's, which the grazing ray passes)
    # shadows the ground at x - RUN * GRATE_Y[0].
    for k in range(SLATS):
        right = GRATE_EDGE_X + RUN * GRATE_Y[0] - k * SLAT_PERIOD
        g.box_node("slat %d" % (k + 1), (right - SLAT_WIDTH, GRATE_Y[0], -1.5), (right, GRATE_Y[1], 1.5),
                   grate_material)
    # Cameras: "above" looks down on B's shadow, close, so the bleeding band is a fair share of
    # its pixels; "side" from the front, both slabs in view.
    g.camera("above", (-1.3, 3.6, 2.6), (-1.3, 0.0, 0.0), 0.9, 0.1, 100.0)
    g.camera("side", (-5.0, 7.0, 16.0), (4.0, 2.0, 0.0), 0.9, 0.1, 100.0)
    # The sun: toward +x and up, rays falling 1 in RUN. A directional light shines along its
    # node's -Z: placed toward the sun, looking at the origin.
    to_light = normalize((RUN, 1.0, 0.0))
    g.light("sun", "directional", [40.0 * c for c in to_light], (0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 3.0,
            shadow={"cascades": 1})
    # The spot: on the sun's line through the middle of B's shadow, far enough (80 units) that
    # its rays are nearly the sun's (the grate's shadow 1.25 times as wide), so its bleeding
    # falls in about the same place; its narrow cone covers B, the grate and their shadows.
    middle = (-1.35, 0.0, 0.0)
    spot = [middle[i] + 80.0 * to_light[i] for i in range(3)]
    g.light("spot", "spot", spot, (1.5, 1.5, 0.0), (1.0, 1.0, 1.0), 10000.0,
            inner=math.radians(3.5), outer=math.radians(5.0))
    os.makedirs(sys.argv[1], exist_ok=True)  # a fresh scratch folder is the usual target
    g.write(os.path.join(sys.argv[1], "stacked_occluders.gltf"), "stacked_occluders.bin")


if __name__ == "__main__":
    main()
