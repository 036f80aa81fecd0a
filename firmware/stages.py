#!/usr/bin/env python3
"""Instructions by pipeline stage, from a QEMU run of the firmware.

Reads the log of `qemu-system-arm ... -d in_asm,exec,nochain` (a pipe, read as it is written): the instructions of
each translated block, and each execution of a block. Every execution adds one to each instruction of its block
(with `nochain` QEMU logs every block it enters; a block left early by a fault would be over-counted, and the
firmware has none). Each instruction's address is then named by `arm-none-eabi-addr2line -i -f`, which lists the
functions inlined at it, innermost first, and charged to the first stage whose function appears in that list (so
the position stage inlined into binning counts as the vertex stage, not as binning). Instructions outside the
frames (start-up, stack painting, the timer check, printing) fall in no stage.

The firmware draws each frame twice, the same way: timed, then untimed with its depths folded into a second
checksum (the only work the second adds, a stage of its own left out of the shares). So every stage's count per
render is its count per frame.

Usage: stages.py ELF LOG_PIPE RENDERS -- prints instructions per stage, in total and per render (divided by
RENDERS).
"""
import collections
import re
import subprocess
import sys

# The checked renders' depth checksum: no part of a frame a product draws, so in no share.
CHECKING = "checking, untimed renders only: the depths' FNV-1a"

# (stage, functions that mark it), tried in order on each inlined function, innermost first.
STAGES = [
    ("vertex stage: positions, outcodes, snapping", ["VertexCache::position", "VertexCache::miss", "ScreenVertex"]),
    ("vertex stage: varyings (normals, world positions)", ["VertexCache::varyings", "triangle_varyings"]),
    ("set-up: edges, bounding box, coverage test", ["setup_fixed", "Rasterizer::setup", "covers_a_centre"]),
    ("clipping", ["ClipVolume::clip", "Plane::", "Expansion"]),
    ("pixel loop: edges, depth test, interpolation",
     ["raster::fill_", "raster::shared_", "Covered::", "Fragments::push"]),
    ("shading: normals, light, highlight, RGB565",
     ["shade_batch", "::flush", "write_batch", "Triangles::", "Fragments::", "::one", "lit_one",
      "per_pixel_one"]),
    ("clearing the band", ["Target::clear"]),
    ("binning: the triangle loop, rejections, entries", ["BandBins::bin", "BinRun"]),
    ("band draws: the triangle loop, block and entry scan", ["draw::run", "draw_walk", "Walk"]),
    ("display: colours sent, FNV-1a", ["draw_frame", "ChecksumDisplay"]),
    (CHECKING, ["fold_depths"]),
    ("scene: shader variant, matrices", ["Scene::", "Variant::", "Transforms"]),
]


def read_log(path):
    blocks, executed, current = {}, collections.Counter(), None
    trace = re.compile(r"^Trace \d+: 0x[0-9a-f]+ \[[0-9a-f]+/([0-9a-f]+)/")
    with open(path, errors="replace") as log:
        for line in log:
            if line.startswith("Trace"):
                m = trace.match(line)
                if m:
                    executed[int(m.group(1), 16)] += 1
            elif line.startswith("IN:"):
                current = []
            elif line.startswith("0x") and current is not None:
                current.append(int(line[2:10], 16))
            elif line.strip() == "" and current:
                blocks.setdefault(current[0], current)
                current = None
    counts = collections.Counter()
    for start, times in executed.items():
        for pc in blocks.get(start, [start]):
            counts[pc] += times
    return counts


def without_generics(function):
    """`a::B<C<D>>::f` as `a::B::f`, so that marks need not spell type parameters."""
    previous = None
    while previous != function:
        previous, function = function, re.sub(r"<[^<>]*>", "", function)
    return function


def stage_of(elf, counts):
    pcs = sorted(counts)
    out = subprocess.run(["arm-none-eabi-addr2line", "-a", "-i", "-f", "-C", "-e", elf],
                         input="\n".join(f"0x{pc:x}" for pc in pcs), capture_output=True, text=True, check=True)
    stages = collections.Counter()
    functions = None
    lines = out.stdout.split("\n")
    i, pc_index = 0, -1
    names = {}
    while i < len(lines):
        if lines[i].startswith("0x"):
            pc_index += 1
            functions = names.setdefault(pcs[pc_index], [])
            i += 1
        elif lines[i]:
            functions.append(without_generics(lines[i]))
            i += 2
        else:
            i += 1
    for pc, times in counts.items():
        stage = "outside the frames"
        for function in names.get(pc, []):
            found = next((name for name, marks in STAGES if any(mark in function for mark in marks)), None)
            if found:
                stage = found
                break
        stages[stage] += times
    return stages


def main():
    elf, log, renders = sys.argv[1], sys.argv[2], int(sys.argv[3])
    stages = stage_of(elf, read_log(log))
    apart = ("outside the frames", CHECKING)
    inside = sum(v for k, v in stages.items() if k not in apart)
    print(f"{'instructions':>13} {'per render':>11} {'share':>6}  stage ({renders} renders)")
    for name, _ in STAGES + [("outside the frames", [])]:
        v = stages.get(name, 0)
        share = f"{100 * v / inside:5.1f}%" if name not in apart else ""
        print(f"{v:>13,} {v // renders:>11,} {share:>6}  {name}")


if __name__ == "__main__":
    main()
