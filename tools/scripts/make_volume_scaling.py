#!/usr/bin/env python3
"""Writes volume_scaling_<N>.gltf (+ .bin): a torus of about N triangles over a ground, lit by
a spot light, for the shadow volumes' scaling run (tools/bench-volumes.sh).

A torus is closed, so its volume is the classic one (near cap, far cap, side quads on the
silhouette); its silhouette from the light is two rings whose edge count grows with the
square root of the triangle count, while the caps grow with the count itself. The light
looks down on it at 45 degrees, so the shadow falls beside the torus on the ground and the
camera ("view") sees torus, shadow and the volumes' sides.
Run: python3 tools/scripts/make_volume_scaling.py OUT_DIR TRIANGLES
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import GltfBuilder, torus  # noqa: E402


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: python3 tools/scripts/make_volume_scaling.py OUT_DIR TRIANGLES")
    triangles = int(sys.argv[2])
    if triangles < 8:
        sys.exit("TRIANGLES must be at least 8")
    # 2 * segments * sides triangles, the tube twice as finely divided around the ring.
    sides = max(2, round(math.sqrt(triangles / 4)))
    segments = max(2, round(triangles / (2 * sides)))
    g = GltfBuilder()
    ground = g.material("ground", (0.7, 0.7, 0.7), roughness=0.9)
    ring = g.material("torus", (0.6, 0.45, 0.3), roughness=0.5)
    g.box_node("ground", (-12.0, -0.5, -12.0), (12.0, 0.0, 12.0), ground)
    g.node("torus", translation=(0.0, 2.0, 0.0), rotation=(0.2588, 0.0, 0.0, 0.9659),
           mesh=g.mesh("torus", torus(2.0, 0.6, segments, sides), ring))
    g.camera("view", (0.0, 9.0, 12.0), (-1.0, 0.5, -1.5), 0.9, 0.1, 100.0)
    g.light("spot", "spot", (8.0, 10.0, 3.0), (-2.0, 0.0, -1.0), (1.0, 1.0, 1.0), 2000.0,
            inner=math.radians(25.0), outer=math.radians(35.0))
    os.makedirs(sys.argv[1], exist_ok=True)
    name = "volume_scaling_%d" % triangles
    g.write(os.path.join(sys.argv[1], name + ".gltf"), name + ".bin")
    print("%s: %d triangles (%d segments x %d sides)" % (name, 2 * segments * sides, segments, sides))


if __name__ == "__main__":
    main()
