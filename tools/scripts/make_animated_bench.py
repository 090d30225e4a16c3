#!/usr/bin/env python3
"""Writes animated_bench.gltf (+ .bin): the scene of the README's animation benchmark.

A 20 m floor with 24 still boxes, two spot lights each over its own half ("swing_light" over
x < 0, "still_light" over x > 0, their cones apart), and one skinned caster under
swing_light: a 3 m post whose upper half follows a joint that swings 60 degrees each way
over 2 s (animation "swing"). Only swing_light sees a caster move, so with map caching its
map re-renders every frame and still_light's never. Run: python3 tools/scripts/make_animated_bench.py OUT_DIR
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import GltfBuilder, box  # noqa: E402


def translation(x, y, z):
    return [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, x, y, z, 1]  # column-major


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
    g = GltfBuilder()
    floor = g.material("floor", (0.6, 0.6, 0.6), roughness=0.9)
    grey = g.material("boxes", (0.7, 0.5, 0.3), roughness=0.7)
    post = g.material("post", (0.3, 0.5, 0.8), roughness=0.5)
    g.node("floor", translation=(0, -0.25, 0), mesh=g.mesh("floor", box((20, 0.5, 20)), floor))
    cube = g.mesh("box", box((0.8, 0.8, 0.8)), grey)
    for row in range(4):
        for column in range(6):
            x = -8.0 + column * 3.2 if column < 3 else 1.6 + (column - 3) * 3.2
            g.node("box_%d_%d" % (row, column), translation=(x, 0.4, -6.0 + row * 4.0), mesh=cube)

    # The post: a box 0.3 x 3 x 0.3 standing on the floor at (-4, 0, 1); vertices above 1.5 m
    # follow the tip joint, the others the base joint.
    positions, normals, indices = box((0.3, 3.0, 0.3))
    positions = [(p[0], p[1] + 1.5, p[2]) for p in positions]
    joints = [(1, 0, 0, 0) if p[1] > 1.5 else (0, 0, 0, 0) for p in positions]
    weights = [(1.0, 0.0, 0.0, 0.0)] * len(positions)
    mesh = g.skinned_mesh("post", (positions, normals, indices), post, joints, weights)
    base = g.node("post_base", translation=(-4, 0, 1))
    tip = g.node("post_tip", translation=(0, 1.5, 0))
    g.doc["scenes"][0]["nodes"].remove(tip)  # a child of the base, not a root
    g.doc["nodes"][base]["children"] = [tip]
    skin = g.skin([base, tip], [translation(0, 0, 0), translation(0, -1.5, 0)])
    g.node("post", mesh=mesh, skin=skin)
    times = [0.0, 0.5, 1.0, 1.5, 2.0]
    angles = [0.0, 60.0, 0.0, -60.0, 0.0]
    turn = [(0.0, 0.0, math.sin(math.radians(a) / 2), math.cos(math.radians(a) / 2)) for a in angles]
    g.rotation_animation("swing", tip, times, turn)

    g.light("swing_light", "spot", (-4.5, 8, 0), (-4.5, 0, 0), (1, 1, 1), 200.0, inner=0.3, outer=0.5)
    g.light("still_light", "spot", (4.5, 8, 0), (4.5, 0, 0), (1, 1, 1), 200.0, inner=0.3, outer=0.5)
    g.camera("camera", (0, 12, 16), (0, 0, 0), 0.8, 0.5, 100.0)
    g.write(os.path.join(out_dir, "animated_bench.gltf"), "animated_bench.bin")


if __name__ == "__main__":
    main()
