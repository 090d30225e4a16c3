# Sourced by tools/bench-volumes*.sh: one light's figures from engine-render's --stats files.
# shellcheck shell=bash

# Frame median/p99/max, the light's shadow ms, and (volume) silhouette edges, cap triangles
# and stencil fragments (the samples that changed the count: the volumes' fill) of the last
# frame; "-" where the light has none.
figures() {  # STATS.json LIGHT
  python3 -c 'import json, sys
s = json.load(open(sys.argv[1]))
light = next(l for l in s["shadow_maps"] if l["light"] == sys.argv[2])
plugin = next(l for l in s["plugins"]["shadowmap_plugin"]["lights"] if l["light"] == sys.argv[2])
print("%.1f %.1f %.1f %s %s %s %s" % (s["frame_ms_median"], s["frame_ms_p99"], s["frame_ms_max"],
      "%.1f" % light["map_ms"] if light["map_ms"] is not None else "-",
      plugin.get("silhouette_edges", "-"), plugin.get("cap_triangles", "-"),
      plugin.get("stencil_fragments", "-")))' "$1" "$2"
}
FIGURES_HEADER="frame-median frame-p99 frame-max shadow-ms silhouette-edges cap-triangles stencil-fragments"

# The light's error and error off edges (percent) from a --truth run's --stats.
errors() {  # STATS.json LIGHT
  python3 -c 'import json, sys
light = next(l for l in json.load(open(sys.argv[1]))["lights"] if l["light"] == sys.argv[2])
print("%.3f %.3f" % (light["error"], light["error_noedge"]))' "$1" "$2"
}
ERRORS_HEADER="error% error-off-edges%"
