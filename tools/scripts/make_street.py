#!/usr/bin/env python3
"""Writes a street at night lit by N shadowed lamps: the scene of the many-lights benchmark.

A road between two raised pavements and two rows of house fronts, running from z = 0 toward
-Z. Along the pavements stand N lamp posts, alternating sides every 4 m (8 m between posts on
one side), lamp k at z = -4k on the left (even k) or the right (odd k). Each post holds an
arm over the pavement with a lamp hanging from it: a spot light ("lamp_007", its node named
the same) aimed down and a little toward the road, narrow (outer cone 0.6 rad) and ranged
(9 m), so it lights only its own pool, shadowed by a 1024 standard map with pcf. Every pool
holds casters whose shadows fall inside it: the post itself, a bench, a crate or bollards,
now and then a ball.

A camera "walker" at eye height walks down the middle of the road looking along it
(animation "walk", linear, at --pace metres per second from 12 m before the first lamp to
12 m past the last); engine-render --animate walk (or all) follows it. Its far plane (120 m)
sees about 30 lamps at a time, so a longer street adds lamps behind and far ahead, not in
view: what a real street asks of a many-lights renderer.

--swinging K: K lamps swing on their hangers (animation "swing", a pendulum of +-0.15 rad,
2 s a period, each lamp in its own phase), so their shadows move every frame. They are spread
over the lamps the walker sees in its first seconds (the first 100 m), since a lamp swinging
out of view costs a renderer nothing and would measure nothing.

--no-shadows: every lamp's shadow is {"variant": "none"}: the unshadowed baseline of the same
street (the lamps' own extras would win over a plugin-wide default variant).

Usage: python3 tools/scripts/make_street.py OUT_DIR [--lamps N] [--swinging K] [--no-shadows]
[--pace M_PER_S]; writes OUT_DIR/street_N.gltf (+ .bin), street_N_swing_K.gltf with
--swinging, with "_noshadow" before ".gltf" with --no-shadows.
"""
import argparse
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(__file__))
from gltf_builder import GltfBuilder, box, icosphere  # noqa: E402

SPACING = 4.0  # metres along the street between consecutive lamps (alternating sides)
ROAD_HALF = 3.5  # the road is |x| < 3.5; pavements 3.5 .. 8.5, house fronts beyond
PAVEMENT_TOP = 0.15
POST_X, HANGER_X, HANGER_Y = 5.9, 5.0, 4.3  # |x| of the post and of the arm's end, its height
LAMP_DROP = 0.5  # the lamp hangs this far below the arm (the pendulum's length)
AIM_X = 4.6  # |x| on the pavement each lamp is aimed at: down, a little toward the road
SHADOW = {"variant": "standard", "resolution": 1024, "filter": "pcf"}
NO_SHADOW = {"variant": "none"}
SWING_RAD, SWING_PERIOD = 0.15, 2.0
SWING_SPAN = 100.0  # swinging lamps are spread over the lamps within this many metres of z = 0
EYE_HEIGHT, LEAD = 1.7, 12.0


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out_dir")
    parser.add_argument("--lamps", type=int, default=64, help="lamps in all (default 64)")
    parser.add_argument("--swinging", type=int, default=0, help="lamps that swing (default 0)")
    parser.add_argument("--no-shadows", action="store_true", help='every lamp\'s shadow {"variant": "none"}')
    parser.add_argument("--pace", type=float, default=10.0, help="the walker's speed, m/s (default 10)")
    args = parser.parse_args()
    if args.lamps < 1:
        parser.error("--lamps must be at least 1")
    if not 0 <= args.swinging <= args.lamps:
        parser.error("--swinging must be between 0 and --lamps")
    if args.pace <= 0:
        parser.error("--pace must be positive")
    return args


def swinging_lamps(lamps, count):
    """`count` lamp indices spread evenly over the lamps within SWING_SPAN metres of the
    walk's start (or over more, when they hold fewer), alternating sides."""
    span = min(lamps, max(count, int(SWING_SPAN / SPACING) + 1))
    chosen = []
    for i in range(count):
        index = int((i + 0.5) * span / count)
        if index % 2 != i % 2:  # lamps alternate sides: even left, odd right
            index = index + 1 if index + 1 < span else index - 1
        while index in chosen:  # as many swinging lamps as the span holds: the next free one
            index = (index + 1) % span
        chosen.append(index)
    return sorted(chosen)


def main():
    args = arguments()
    g = GltfBuilder()
    asphalt = g.material("asphalt", (0.12, 0.12, 0.13), roughness=0.9)
    paving = g.material("paving", (0.55, 0.53, 0.5), roughness=0.85)
    facade = g.material("facade", (0.45, 0.32, 0.25), roughness=0.8)
    iron = g.material("iron", (0.1, 0.12, 0.1), metallic=0.8, roughness=0.45)
    glass = g.material("lamp_glass", (0.9, 0.85, 0.7), roughness=0.2)
    wood = g.material("wood", (0.5, 0.33, 0.18), roughness=0.7)
    crate_wood = g.material("crate", (0.62, 0.48, 0.28), roughness=0.75)
    stone = g.material("bollard", (0.5, 0.5, 0.48), roughness=0.8)
    brass = g.material("brass", (0.85, 0.65, 0.3), metallic=0.9, roughness=0.3)

    lamps = args.lamps
    last_z = -SPACING * (lamps - 1)
    start_z, end_z = LEAD, last_z - LEAD
    length = start_z - end_z
    mid_z = (start_z + end_z) / 2
    # The ground under everything, its top at y = 0 (the road); the pavements on it.
    g.node("ground", translation=(0, -0.1, mid_z), mesh=g.mesh("ground", box((20.0, 0.2, length + 20.0)), asphalt))
    pavement = g.mesh("pavement", box((5.0, PAVEMENT_TOP, length + 20.0)), paving)
    for side, sign in (("left", -1), ("right", 1)):
        g.node("pavement_" + side, translation=(sign * 6.0, PAVEMENT_TOP / 2, mid_z), mesh=pavement)
    # House fronts in blocks of 16 m, of varying height: receivers outside every cone.
    houses = random.Random(1)
    house_meshes = {}
    block_count = int(math.ceil((length + 20.0) / 16.0))
    for side, sign in (("left", -1), ("right", 1)):
        for block in range(block_count):
            height = houses.choice((6.0, 8.0, 9.0, 12.0))
            z = start_z + 10.0 - 16.0 * block - 8.0
            if height not in house_meshes:
                house_meshes[height] = g.mesh("house_%g" % height, box((2.0, height, 15.6)), facade)
            g.node("house_%s_%d" % (side, block), translation=(sign * 9.5, height / 2, z), mesh=house_meshes[height])

    post = g.mesh("post", box((0.18, HANGER_Y + 0.1, 0.18)), iron)
    arm = g.mesh("arm", box((POST_X - HANGER_X + 0.2, 0.08, 0.08)), iron)
    chain = g.mesh("chain", box((0.03, LAMP_DROP - 0.1, 0.03)), iron)
    head = g.mesh("lamp_head", box((0.36, 0.12, 0.36)), glass)
    bench = g.mesh("bench", box((0.5, 0.45, 1.6)), wood)
    crate = g.mesh("crate", box((0.6, 0.6, 0.6)), crate_wood)
    bollard = g.mesh("bollard", box((0.2, 0.9, 0.2)), stone)
    ball = g.mesh("ball", icosphere(0.3, 1), brass)

    swinging = set(swinging_lamps(lamps, args.swinging))
    hangers = {}
    for k in range(lamps):
        sign = -1 if k % 2 == 0 else 1
        z = -SPACING * k
        name = "lamp_%03d" % k
        scatter = random.Random(1000 + k)  # per lamp: street_64 is the first 64 lamps of street_128
        g.node("post_%03d" % k, translation=(sign * POST_X, (HANGER_Y + 0.1) / 2, z), mesh=post)
        g.node("arm_%03d" % k, translation=(sign * (POST_X + HANGER_X) / 2, HANGER_Y, z), mesh=arm)
        # The hanger: a pivot at the arm's end holding the chain, the lamp's head and the light.
        hanger = g.node("hanger_%03d" % k, translation=(sign * HANGER_X, HANGER_Y, z))
        parts = [g.node("chain_%03d" % k, translation=(0, -LAMP_DROP / 2, 0), mesh=chain),
                 # Just above the light: outside its cone, so it shades nothing of the pool.
                 g.node("head_%03d" % k, translation=(0, -LAMP_DROP + 0.08, 0), mesh=head)]
        eye = (0.0, -LAMP_DROP, 0.0)
        aim = (sign * (AIM_X - HANGER_X), PAVEMENT_TOP - HANGER_Y, scatter.uniform(-0.3, 0.3))
        parts.append(g.light(name, "spot", eye=eye, target=aim, color=(1.0, 0.82, 0.55), intensity=110.0,
                             range_=9.0, inner=0.42, outer=0.6, shadow=NO_SHADOW if args.no_shadows else SHADOW))
        g.parent(hanger, parts)
        hangers[k] = hanger
        # Casters in the pool (its radius at the pavement about 2.5 m around x = AIM_X): a
        # bench beside the post, toward or away along the street, and on the road's side a
        # crate (turned a little) or two bollards at the kerb; every fourth pool a ball.
        along = scatter.choice((-1, 1))
        g.node("bench_%03d" % k, translation=(sign * 5.95, PAVEMENT_TOP + 0.225, z + along * scatter.uniform(1.2, 1.7)),
               mesh=bench)
        if scatter.random() < 0.5:
            turn = scatter.uniform(-0.6, 0.6)
            g.node("crate_%03d" % k, translation=(sign * 4.1, PAVEMENT_TOP + 0.3, z - along * scatter.uniform(0.8, 1.5)),
                   rotation=(0.0, math.sin(turn / 2), 0.0, math.cos(turn / 2)), mesh=crate)
        else:
            for i, dz in enumerate((-1.1, 1.1)):
                g.node("bollard_%03d_%d" % (k, i), translation=(sign * 3.75, PAVEMENT_TOP + 0.45, z + dz), mesh=bollard)
        if k % 4 == 3:
            g.node("ball_%03d" % k, translation=(sign * 4.9, PAVEMENT_TOP + 0.3, z - along * 1.9), mesh=ball)

    # The walker: eye height, looking along the street and a little down; only its position moves.
    eye = (0.0, EYE_HEIGHT, start_z)
    walker = g.camera("walker", eye=eye, target=(0.0, EYE_HEIGHT - 1.2, start_z - 20.0), yfov=0.9, znear=0.1,
                      zfar=120.0)
    seconds = length / args.pace
    g.translation_animation("walk", walker, [0.0, seconds], [eye, (0.0, EYE_HEIGHT, end_z)])

    if swinging:
        # Keys every eighth of a period over the whole walk (sin sampled: the pendulum's ease at
        # its ends), about the street's axis (z): the lamp swings across the pavement.
        steps = int(math.ceil(seconds / SWING_PERIOD * 8))
        times = [i * SWING_PERIOD / 8 for i in range(steps + 1)]
        channels = []
        for order, k in enumerate(sorted(swinging)):
            phase = 2 * math.pi * order / len(swinging)
            angles = [SWING_RAD * math.sin(2 * math.pi * t / SWING_PERIOD + phase) for t in times]
            channels.append((hangers[k], "rotation", times,
                             [(0.0, 0.0, math.sin(a / 2), math.cos(a / 2)) for a in angles]))
        g.animation("swing", channels)

    stem = "street_%d" % lamps + ("_swing_%d" % args.swinging if args.swinging else "") + \
        ("_noshadow" if args.no_shadows else "")
    os.makedirs(args.out_dir, exist_ok=True)
    g.write(os.path.join(args.out_dir, stem + ".gltf"), stem + ".bin")
    print(os.path.join(args.out_dir, stem + ".gltf"))


if __name__ == "__main__":
    main()
