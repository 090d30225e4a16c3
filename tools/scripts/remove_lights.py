#!/usr/bin/env python3
"""remove_lights.py IN.gltf OUT.gltf: the scene without its KHR_lights_punctual lights (the
extension's lights, every node's reference to them, and the extension's use), as most sample
files come: for tests of what the tools do with a scene that brings no light."""
import json
import sys

scene = json.load(open(sys.argv[1]))
scene.get("extensions", {}).pop("KHR_lights_punctual", None)
scene["extensionsUsed"] = [e for e in scene.get("extensionsUsed", []) if e != "KHR_lights_punctual"]
for node in scene.get("nodes", []):
    node.get("extensions", {}).pop("KHR_lights_punctual", None)
json.dump(scene, open(sys.argv[2], "w"))
