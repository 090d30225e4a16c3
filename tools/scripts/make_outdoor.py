#!/usr/bin/env python3
"""Writes outdoor.gltf (+ .bin): a large outdoor scene for cascaded shadow maps.

A 1 km square ground, thin posts (2.5 m tall, 15 cm wide) every 3 m along both kerbs of a
street 2 to 29 m ahead of a street-level camera, four buildings far down the street, and a
sun 35 degrees above the horizon. The same scene as tests/support/OutdoorScene.h (whose
boxes the render tests shadow analytically); this one is for engine-render --truth and the
bench. Run: python3 tools/scripts/make_outdoor.py OUT_DIR
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import GltfBuilder  # noqa: E402


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
    g = GltfBuilder()
    ground = g.material("ground", (0.55, 0.55, 0.5), roughness=0.95)
    wood = g.material("wood", (0.55, 0.38, 0.2), roughness=0.7)
    stone = g.material("stone", (0.7, 0.68, 0.62), roughness=0.8)
    g.box_node("ground", (-500, -0.5, -500), (500, 0, 500), ground)
    for i in range(10):
        for x in (-3.0, 3.0):
            z = -2.0 - 3.0 * i
            g.box_node("post_%d_%s" % (i, "left" if x < 0 else "right"), (x - 0.075, 0, z - 0.075),
                       (x + 0.075, 2.5, z + 0.075), wood)
    for i in range(4):
        x, z = (25.0 if i % 2 else -25.0), -120.0 - 60.0 * i
        g.box_node("building_%d" % i, (x - 8, 0, z - 10), (x + 8, 20 + 5 * i, z + 10), stone)
    g.camera("street_camera", (0, 1.7, 0), (0, 1.0, -20), 0.9, 0.1, 300.0)
    elevation, azimuth = math.radians(35.0), 0.6
    to_sun = (-math.cos(elevation) * math.sin(azimuth), math.sin(elevation), -math.cos(elevation) * math.cos(azimuth))
    g.light("sun", "directional", [100 * c for c in to_sun], (0, 0, 0), (1.0, 0.97, 0.9), 3.0)
    g.write(os.path.join(out_dir, "outdoor.gltf"), "outdoor.bin")


if __name__ == "__main__":
    main()
