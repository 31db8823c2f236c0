#!/usr/bin/env bash
# `rt bvh-dump` and `rt bvh-cost` (apps/bvh_cost.h; CTest: Cli.BvhCostCountsAGivenTree): the
# reference's tree, dumped and costed as a student's would be, costs what the reference costs
# itself; a valid but poor tree (one leaf holding every primitive) costs more; a tree whose root
# box no longer holds its primitives, and a truncated file, are refused with one line.
#   bvh_cost_cli.sh RT SCENE
set -u -o pipefail
rt=$1 scene=$2
size=(--width 64 --height 48)  # few rays: the one-leaf tree tests every primitive on each
work=$(mktemp -d /tmp/rt-bvh-cost-XXXXXX)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
cost_of() { sed -n 's/^traversal cost \([0-9.]*\) per ray.*/\1/p' <<< "$1"; }
le32() { printf "\\x$(printf %02x $(($1 & 255)))\\x$(printf %02x $(($1 >> 8 & 255)))\\x$(printf %02x $(($1 >> 16 & 255)))\\x$(printf %02x $(($1 >> 24 & 255)))"; }

own=$("$rt" bvh-cost "$scene" "${size[@]}") || fail "rt bvh-cost on its own tree"
"$rt" bvh-dump "$scene" -o "$work/tree.bin" || fail "rt bvh-dump"
given=$("$rt" bvh-cost "$scene" "${size[@]}" --tree "$work/tree.bin") || fail "rt bvh-cost --tree"
echo "own tree: $own"
[ "$(cost_of "$own")" = "$(cost_of "$given")" ] && [ -n "$(cost_of "$own")" ] ||
  fail "the dumped tree costs $(cost_of "$given"), the tree itself $(cost_of "$own")"

# One leaf of every primitive: the header with one node, the root's bytes with first 0 and
# count P, then the primitive ids as dumped.
nodes=$(od -An -t u8 -j 8 -N 8 "$work/tree.bin" | tr -d ' ')
prims=$(od -An -t u8 -j 16 -N 8 "$work/tree.bin" | tr -d ' ')
{
  head -c 8 "$work/tree.bin"; le32 1; le32 0; le32 "$prims"; le32 0
  dd if="$work/tree.bin" bs=1 skip=24 count=12 status=none; le32 0
  dd if="$work/tree.bin" bs=1 skip=40 count=12 status=none; le32 "$prims"
  tail -c $((prims * 4)) "$work/tree.bin"
} > "$work/leaf.bin"
leaf=$("$rt" bvh-cost "$scene" "${size[@]}" --tree "$work/leaf.bin") || fail "a one-leaf tree is refused"
echo "one leaf: $leaf"
awk -v a="$(cost_of "$leaf")" -v b="$(cost_of "$own")" 'BEGIN { exit !(a > 10 * b) }' ||
  fail "a one-leaf tree of $prims primitives does not cost far more than the reference's $nodes nodes"

# The root box shrunk to a point at the origin: its primitives stick out.
{ head -c 24 "$work/tree.bin"; head -c 12 /dev/zero; dd if="$work/tree.bin" bs=1 skip=36 count=4 status=none
  head -c 12 /dev/zero; tail -c +53 "$work/tree.bin"; } > "$work/shrunk.bin"
"$rt" bvh-cost "$scene" "${size[@]}" --tree "$work/shrunk.bin" > "$work/out" 2>&1 && fail "a shrunk root box is costed"
grep -q "shrunk.bin: not a valid BVH of" "$work/out" || { cat "$work/out"; fail "no one-line refusal"; }
[ "$(wc -l < "$work/out")" -eq 1 ] || { cat "$work/out"; fail "more than one line"; }
head -c 1000 "$work/tree.bin" > "$work/cut.bin"
"$rt" bvh-cost "$scene" "${size[@]}" --tree "$work/cut.bin" > "$work/out" 2>&1 && fail "a truncated tree is costed"
grep -q "cut.bin: its counts do not match its size" "$work/out" || { cat "$work/out"; fail "truncated: $(cat "$work/out")"; }
echo "ok: the dumped tree costs as much as the tree; a poor tree more; broken trees refused"
