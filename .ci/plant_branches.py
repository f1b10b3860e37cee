#!/usr/bin/env python3
"""Lines of generic code that branch on the plant or on the 3-D approach (issue 41's
structure target): a line outside test modules that both names the plant or the 3-D
approach (`PlantModel`, `BuiltPlant`, `ThreeDof`, `SixDof` as words — not a type
named after the 6-DOF model such as `SixDofTrimError` —, `three_dimensional`,
`three_d`, `LATERAL`, `LateralLoop`, an `Option<…Lateral…>`, `Some(lateral…)`, a
`.lateral` field, `lateral.is_some()`/`.as_ref()`/`.map()`/…) and branches (`if`, `match`,
`=>`, `?`, `else` (a `let … else` too), `.then(`, `.map(`, `.map_or(`, `.and_then(`,
`.filter(`, `.zip(`, `.is_some_and(`, `while`). The setup code and the
registries, where choosing the parts is the job, are left out (SETUP below). Prints the
count per file and a last line `lines N files M`; with `--max N` exits 1 when there are
more than N. usage: plant_branches.py [--max N] DIR..."""
import os, re, sys

SETUP = {
    # building the loop for a configuration
    "crates/deckland/src/simulation/setup.rs",
    "crates/deckland/src/simulation/pitch_setup.rs",
    "crates/deckland/src/simulation/lateral/build.rs",
    "crates/deckland/src/experiments/lateral_step/setup.rs",
    # the Python environment's configuration
    "python/src/gym/config.rs",
    # the plant registry: the models by name, and the built plant of each
    "crates/deckland/src/aircraft/plant.rs",
    "crates/deckland/src/aircraft/built_plant.rs",
    # the front end's registry: each model's trim/linearize commands, `--model` value and
    # approach in words
    "crates/deckland-cli/src/commands/models/mod.rs",
    "crates/deckland-cli/src/commands/models/names.rs",
    # reading scenario files
    "crates/deckland/src/scenario/aircraft.rs",
}
TOKEN = re.compile(
    r"three_dimensional|\bthree_d\b|\bThreeDof\b|\bSixDof\b|PlantModel|BuiltPlant|\bLATERAL\b|LateralLoop"
    r"|flies_three_dimensional|Some\(\s*\w*lateral\w*|\w*lateral\w*\.(is_some|is_none|as_ref|as_mut|map|and_then|then)\b"
    r"|\.lateral\b|is_lateral|\bsix_dof\b|Option<\w*Lateral"
)
BRANCH = re.compile(
    r"\bif\b|\bmatch\b|=>|\.then\(|\.then_some\(|\bwhile\b|\.map\(|\.and_then\(|\.filter\(|\?"
    r"|\belse\b|\.map_or(_else)?\(|\.zip\(|\.is_some_and\(|\.is_none_or\("
)

args = sys.argv[1:]
limit = None
if "--max" in args:
    i = args.index("--max")
    limit = int(args[i + 1])
    del args[i : i + 2]
hits = {}
for top in args or ["crates/deckland/src", "crates/deckland-cli/src", "python/src"]:
    for root, dirs, files in os.walk(top):
        for f in files:
            path = os.path.join(root, f)
            if not f.endswith(".rs") or path in SETUP or f == "tests.rs" or f.endswith("_tests.rs"):
                continue
            lines = open(path, encoding="utf-8").read().split("\n")
            # the inline test module at the end of a file: `#[cfg(test)]` then `mod NAME {`
            # (a `#[cfg(test)]` on any other item, or on `mod tests;`, cuts nothing)
            cut = next(
                (k for k, l in enumerate(lines)
                 if re.match(r"\s*#\[cfg\(test\)\]", l)
                 and k + 1 < len(lines) and re.match(r"\s*(pub(\(\w+\))?\s+)?mod\s+\w+\s*\{", lines[k + 1])),
                len(lines),
            )
            for k, line in enumerate(lines[:cut]):
                code = line.split("//")[0]
                if TOKEN.search(code) and BRANCH.search(code):
                    hits.setdefault(path, []).append(k + 1)
count = sum(len(v) for v in hits.values())
for path, numbers in sorted(hits.items(), key=lambda kv: (-len(kv[1]), kv[0])):
    print(len(numbers), path, ",".join(map(str, numbers)))
print(f"lines {count} files {len(hits)}")
if limit is not None and count > limit:
    print(f"error: {count} lines branch on the plant or the 3-D approach, more than the {limit} allowed", file=sys.stderr)
    sys.exit(1)
