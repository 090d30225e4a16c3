#!/usr/bin/env python3
"""Writes content/scenes/showcase.gltf (+ .bin): the scene the README renders.

A closed floor slab, a box resting on it (contact), an icosphere and a torus hovering,
a thin plank on two posts (a thin caster), and a double-sided open canopy (an open
caster), lit by one spot, one directional and one point light, each shadowed.
Run from the repository root: python3 tools/scripts/make_showcase.py [OUT_DIR]
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import GltfBuilder, output_dir, box, icosphere, quad, torus  # noqa: E402


def main():
    # An optional output directory (the validation test writes to a scratch one).
    out_dir = output_dir(sys.argv)
    g = GltfBuilder()
    floor_mat = g.material("floor", (0.75, 0.75, 0.72), roughness=0.9)
    red = g.material("red", (0.8, 0.15, 0.1), roughness=0.4)
    blue = g.material("blue", (0.15, 0.3, 0.8), roughness=0.3)
    gold = g.material("gold", (0.9, 0.7, 0.3), metallic=0.8, roughness=0.35)
    wood = g.material("wood", (0.55, 0.38, 0.2), roughness=0.7)
    cloth = g.material("cloth", (0.3, 0.7, 0.35), roughness=0.8, double_sided=True)

    g.node("floor", translation=(0, -0.1, 0), mesh=g.mesh("floor", box((20, 0.2, 20)), floor_mat))
    g.node("box", translation=(-2.0, 0.75, 0.5), rotation=(0, math.sin(0.3), 0, math.cos(0.3)),
           mesh=g.mesh("box", box((1.5, 1.5, 1.5)), red))
    g.node("sphere", translation=(1.2, 1.6, -0.8), mesh=g.mesh("sphere", icosphere(0.9, 3), blue))
    g.node("torus", translation=(2.6, 0.6, 2.2), rotation=(math.sin(0.35), 0, 0, math.cos(0.35)),
           mesh=g.mesh("torus", torus(0.8, 0.25, 48, 24), gold))
    post = g.mesh("post", box((0.15, 1.0, 0.15)), wood)
    g.node("post_left", translation=(-1.4, 0.5, 3.2), mesh=post)
    g.node("post_right", translation=(0.6, 0.5, 3.2), mesh=post)
    g.node("plank", translation=(-0.4, 1.025, 3.2), mesh=g.mesh("plank", box((2.4, 0.05, 0.6)), wood))
    g.node("canopy", translation=(-3.5, 2.2, -2.5), rotation=(math.sin(0.2), 0, 0, math.cos(0.2)),
           mesh=g.mesh("canopy", quad(2.0, 1.6), cloth))

    g.camera("main_camera", eye=(8.5, 6.5, 10.0), target=(0, 0.6, 0.5), yfov=0.7, znear=0.1, zfar=60.0)
    g.light("spot_light", "spot", eye=(-4.0, 7.0, 5.0), target=(0.0, 0.0, 0.5), color=(1.0, 0.92, 0.8),
            intensity=180.0, inner=0.35, outer=0.6,
            shadow={"variant": "standard", "resolution": 2048, "filter": "pcf"})
    g.light("sun", "directional", eye=(6.0, 10.0, -3.0), target=(0, 0, 0), color=(0.9, 0.95, 1.0),
            intensity=1.6, shadow={"variant": "standard", "resolution": 2048, "filter": "pcf"})
    g.light("point_light", "point", eye=(0.2, 2.6, 1.6), target=(0, 0, 1.6), color=(1.0, 0.75, 0.45),
            intensity=14.0, range_=25.0,
            shadow={"variant": "standard", "resolution": 1024, "filter": "pcf"})
    g.write(os.path.join(out_dir, "showcase.gltf"), "showcase.bin")


if __name__ == "__main__":
    main()
