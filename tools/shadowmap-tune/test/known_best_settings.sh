#!/usr/bin/env bash
# On scenes whose best setting is known, the tuner picks it. With a budget no setting can
# exceed, the choice is the lowest error (expected cost, not time, breaks exact ties), and at one size,
# format and filter the variants compete on error alone (the offset fit is error-driven
# too), so the result does not depend on the machine's load.
#  - closed boxes under a low light, at the light's normal offset 0 (the scene pins it, see
#    make_tune_scenes.py): backface measured 0.412 % area error, standard with its fitted
#    polygon offset 0.420 %, woo 0.427 % (1024 d24 nearest, 160x120, both cameras; most of
#    it is the hard edges' partial pixels, which all three share; off edges backface errs on
#    no pixel, the others on one). The offset fit also moves standard's normal offset, and
#    at 0.25 standard shades backface's very pixels (the same error to the last digit):
#    such a tie goes to the setting met first, backface, and is no win by error;
#  - open cards: backface would be standard by another name (the plugin draws open casters
#    two-sided), so it is never measured and never chosen.
source "$(dirname "$0")/common.sh" "$@"

one_setting=(--resolutions 1024 --depth-formats d24 --filters nearest)
tune "${one_setting[@]}" --scene "$work/closed.gltf" --budget-ms 100000 --out "$work/closed_tuned.gltf" \
  --report "$work/closed.json"
variant=$(json "$work/closed.json" "r['lights'][0]['after']['setting']['variant']")
[[ $variant == backface ]] || fail "closed casters: chose $variant, expected backface"
# Backface wins by error at the light's normal offset: every other setting measured there
# (all but the fit's points that move the normal offset off 0) errs more, and nothing
# measured errs less.
json "$work/closed.json" "min(m['error'] for m in r['lights'][0]['measured'] if m['setting'].get('variant') != 'backface' \
  and m['setting'].get('normal_offset', 0) == 0) > r['lights'][0]['after']['error'] \
  and min(m['error'] for m in r['lights'][0]['measured']) >= r['lights'][0]['after']['error']" | grep -qx True \
  || fail "closed casters: backface is no better than the others"
grep -q '"variant":"backface"' "$work/closed_tuned.gltf" || fail "closed casters: backface not written into the scene"

tune "${one_setting[@]}" --scene "$work/open.gltf" --budget-ms 100000 --out "$work/open_tuned.gltf" --report "$work/open.json" 2> "$work/open.log"
grep -q 'backface left out: no caster is closed (e.g. "card_a")' "$work/open.log" \
  || fail "open casters: no note that backface is left out: $(cat "$work/open.log")"
json "$work/open.json" "[m['setting'].get('variant') for m in r['lights'][0]['measured']]" | grep -q backface \
  && fail "open casters: backface was measured"
variant=$(json "$work/open.json" "r['lights'][0]['after']['setting']['variant']")
[[ $variant != backface ]] || fail "open casters: chose backface"
# The choice is the most accurate of what was measured.
json "$work/open.json" "r['lights'][0]['after']['error'] <= min(m['error'] for m in r['lights'][0]['measured']) + 1e-4" \
  | grep -qx True || fail "open casters: the choice is not the most accurate measured"
echo "ok: closed -> backface, open -> $variant"
