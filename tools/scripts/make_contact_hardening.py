#!/usr/bin/env python3
"""Writes contact_hardening.gltf (+ .bin): the contact-hardening scene of
tests/shadowmap/render/SoftShadowTest.cpp, for engine-render --truth and the bench.

A 16 x 16 floor (top at y = 0), two equal 3 x 3 x 0.1 slabs, a low one 0.25 to 0.35 above
the floor (x -4.5 to -1.5) and a high one 2.5 to 2.6 above it (x 1.5 to 4.5), and a sun with
an angular diameter of 0.15 rad: its penumbra is thin under the low slab and several times
wider under the high one, which a soft filter (pcss) must follow and a fixed one (pcf)
cannot. The numbers are the test's; change them there and here together.
Run: python3 tools/scripts/make_contact_hardening.py OUT_DIR
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import GltfBuilder  # noqa: E402


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: python3 tools/scripts/make_contact_hardening.py OUT_DIR")
    g = GltfBuilder()
    floor = g.material("floor", (0.7, 0.7, 0.7), roughness=0.9)
    slab = g.material("slab", (0.6, 0.45, 0.3), roughness=0.7)
    g.box_node("floor", (-8.0, -0.5, -8.0), (8.0, 0.0, 8.0), floor)
    g.box_node("low", (-4.5, 0.25, -2.0), (-1.5, 0.35, 1.0), slab)
    g.box_node("high", (1.5, 2.5, -2.0), (4.5, 2.6, 1.0), slab)
    # The test's camera (tests/support/TestScenes.h cameraLooking: yfov 0.9, near 0.1, far 100).
    g.camera("camera", (0.0, 14.0, 6.0), (0.0, 0.0, -0.5), 0.9, 0.1, 100.0)
    # From behind the slabs, where the sun throws their shadows: the docs' picture.
    g.camera("behind", (0.0, 7.0, -11.0), (0.0, 0.0, -1.0), 0.9, 0.1, 100.0)
    # A directional light shines along its node's -Z: placed toward the sun, looking at the origin.
    length = math.hypot(1.0, 0.35)
    to_sun = (0.0, 1.0 / length, 0.35 / length)
    g.light("sun", "directional", [100.0 * c for c in to_sun], (0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 3.0,
            shadow={"angular_diameter": 0.15, "cascades": 1, "resolution": 2048})
    os.makedirs(sys.argv[1], exist_ok=True)  # a fresh scratch folder is the usual target
    g.write(os.path.join(sys.argv[1], "contact_hardening.gltf"), "contact_hardening.bin")


if __name__ == "__main__":
    main()
