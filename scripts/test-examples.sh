#!/usr/bin/env bash
# Installs datomsim from build/release into a temporary prefix, copies each project of examples/
# out of the source tree, builds it against the installed package, and runs it on generated
# scenes, checking what it wrote:
#   flood            the same hop counts as the built-in flood program;
#   leader-election  every module elects the smallest id, and depths are the hop counts from it;
#   surface-walker   ten walkers make their steps at once, handling the refusals they meet (and
#                    the same seed gives the same run).
set -euo pipefail
cd "$(dirname "$0")/.."

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
cmake --install build/release --prefix "$prefix" > "$work/install.log"
echo "installed into a temporary prefix: $(cd "$prefix" && find . -type f | wc -l) files"

for example in flood leader-election surface-walker; do
  cp -r "examples/$example" "$work/$example"
  cmake -S "$work/$example" -B "$work/$example/build" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release > "$work/$example.configure.log"
  cmake --build "$work/$example/build" -j "$(nproc)" > "$work/$example.build.log"
  echo "built examples/$example outside the tree"
done

datomsim="$prefix/bin/datomsim"
"$datomsim" generate box --size 7,6,3 -o "$work/box.json" > /dev/null
"$datomsim" generate random --count 150 --seed 4 --grid 20,20,4 --random-orientations -o "$work/random.json" > /dev/null

"$work/flood/build/flood-example" run "$work/box.json" --program my-flood --param root=2,3,1 \
  --out "$work/my-flood.json"
"$datomsim" run "$work/box.json" --program flood --root 2,3,1 --out "$work/flood.json"
"$work/leader-election/build/leader-election" run "$work/random.json" \
  --program leader-election --out "$work/leaders.json"
"$work/flood/build/flood-example" run "$work/random.json" --program flood \
  --root "$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); m=min(d["modules"], key=lambda m: m["id"]); print(",".join(map(str, m["cell"])))' "$work/random.json")" \
  --out "$work/flood-from-leader.json"
for run in 1a 1b 2; do
  "$work/surface-walker/build/surface-walker" run scenes/walkers.json --program surface-walker \
    --param steps=25 --seed "${run:0:1}" --trace "$work/walk-$run.jsonl" --out "$work/walk-$run.json"
done

# The viewer from a researcher's executable: the bundle is found beside the installed library.
if [[ -f "$prefix/share/datomsim/viewer.bundle.js" ]]; then
  "$work/surface-walker/build/surface-walker" view "$work/walk-1a.jsonl" -o "$work/walk.html"
  grep -q "datomsim-trace" "$work/walk.html"
  echo "view: $(($(wc -c < "$work/walk.html") / 1024)) KB page from the example's executable"
fi

python3 - "$work" << 'PY'
import glob, json, sys
work = sys.argv[1]
load = lambda name: json.load(open(f"{work}/{name}"))

mine, builtin = load("my-flood.json"), load("flood.json")
assert mine["hops"] == builtin["hops"] and len(mine["hops"]) == 7 * 6 * 3, "flood differs"
print(f"flood: {len(mine['hops'])} hop counts, the built-in flood's; the farthest {max(h[3] for h in mine['hops'])} hops")

scene = load("random.json")
leaders = load("leaders.json")
smallest = min(m["id"] for m in scene["modules"])
assert {row[3] for row in leaders["leader"]} == {smallest}, "not every module elected the smallest id"
depths = {tuple(r[:3]): r[3] for r in leaders["depth"]}
hops = {tuple(r[:3]): r[3] for r in load("flood-from-leader.json")["hops"]}
assert depths == hops, "the tree's depths are not the hop counts from the leader"
print(f"leader-election: all {len(leaders['leader'])} modules elected module {smallest}; depths are its hop counts")

runs = {run: load(f"walk-{run}.json") for run in ("1a", "1b", "2")}
for run, result in runs.items():
    steps, gave_up = result["steps"], result["gave_up"]
    # A walker makes its 25 steps, or gives up after 20 refusals in a row (walled in, or off the
    # floor's edge with no motion left that needs no helper).
    assert len(steps) == 10 and all(s[3] == 25 or g[3] == 1 for s, g in zip(steps, gave_up)), steps
    assert result["motions"] == sum(s[3] for s in steps) and result["max_concurrent_motions"] > 1
refused = sum(r[3] for r in runs["1a"]["refusals"])
assert refused > 0, "no walker met a refusal: the example shows no handling"
assert runs["1a"] == runs["1b"] and runs["1a"] != runs["2"], "seeds do not decide the run"
assert open(f"{work}/walk-1a.jsonl").read() == open(f"{work}/walk-1b.jsonl").read()
finished = sum(1 for s in runs["1a"]["steps"] if s[3] == 25)
print(f"surface-walker: 10 walkers, {finished} made their 25 steps (the others gave up); up to "
      f"{runs['1a']['max_concurrent_motions']} motions at once; {refused} refusals met and handled "
      f"(seed 1); the same seed, the same trace")
PY

# The Python package from the prefix, as docs/python.md installs it: imported outside the tree,
# and found by the installed `datomsim sweep`.
if package="$(ls -d "$prefix"/lib*/python3/dist-packages 2> /dev/null)" &&
  [[ -f "$package/datomsim/__init__.py" ]]; then
  (cd "$work" && PYTHONPATH="$package" /usr/bin/python3 - "$package" << 'PY'
import sys
import datomsim
assert datomsim.__file__.startswith(sys.argv[1]), datomsim.__file__
found = [(len(datomsim.reach(datomsim.arch(h), goal=(6, 5, 2), start=(0, 0, 2)).cells)) for h in (2, 1)]
assert found == [145, 144], found
print(f"python: datomsim imported from the prefix; reach gives {found[0]} and {found[1]} cells")
PY
  )
  printf '{"scenes": [{"generate": "arch", "hole": [1, 2]}], "programs": [{"program": "gradient", "goal": [6, 5, 2]}]}' > "$work/sweep.json"
  "$datomsim" --quiet sweep "$work/sweep.json" -o "$work/sweep.csv" --workers 1
  [[ "$(wc -l < "$work/sweep.csv")" == 3 ]] || { echo "the installed sweep wrote no rows" >&2; exit 1; }
  echo "python: the installed datomsim sweep ran 2 cases"
else
  echo "python: the package was not built, so not installed (docs/python.md)"
fi
