#!/usr/bin/env bash
# Measures the firmware for docs/firmware.md:
# - flash (.text + .rodata) and RAM (.data + .bss), from the ELF file (arm-none-eabi-size -A);
# - which crate each byte of .text comes from (arm-none-eabi-addr2line) and what .rodata holds (arm-none-eabi-nm);
# - from a run under QEMU with -icount shift=0 (1 ns of virtual time per instruction): instructions per frame and
#   per pixel in each memory layout, the peak stack, and the frame rate they imply at 168 MHz, an estimate at 1
#   instruction per cycle;
# - with --stages, from a second run logging every translated block and every block executed
#   (-d in_asm,exec,nochain, read through a pipe by stages.py): the instructions of each pipeline stage.
# With --look plain or --look textured, all of this for a firmware built with that look's frames alone (in a target
# folder of its own), which links that look's pipeline alone: the code a product showing that look would carry.
# Needs arm-none-eabi-size, -nm and -addr2line (Debian: binutils-arm-none-eabi), qemu-system-arm and, for --stages,
# python3; check.sh, which CI runs, needs none of them but QEMU.
# Usage: firmware/measure.sh [--no-build] [--stages] [--look plain|textured]
set -euo pipefail
cd "$(dirname "$0")"
usage() { echo "usage: $0 [--no-build] [--stages] [--look plain|textured]" >&2; exit 2; }
build=1 stages=0 look=
while [ $# -gt 0 ]; do
    case $1 in
        --no-build) build=0 ;;
        --stages) stages=1 ;;
        --look) [ $# -ge 2 ] || usage; look=$2; shift ;;
        *) usage ;;
    esac
    shift
done
case $look in
    '') target=target features=() ;;
    plain | textured) target=target/look-$look features=(--no-default-features --features "$look") ;;
    *) usage ;;
esac
elf=$target/thumbv7em-none-eabihf/release/rastty-firmware
if [ "$build" = 1 ]; then
    cargo build --release --locked --target-dir "$target" "${features[@]}"
fi
out=$(mktemp)
pipe=$(mktemp -u)
trap 'rm -f "$out" "$pipe"' EXIT

echo "== arm-none-eabi-size -A $elf"
arm-none-eabi-size -A "$elf" | awk '$1 ~ /^\.(vector_table|text|rodata|data|bss|uninit)$/'
arm-none-eabi-size -A "$elf" | awk '
    { size[$1] = $2 }
    END {
        flash = size[".text"] + size[".rodata"]
        printf "flash: .text + .rodata = %d bytes; with .vector_table, %d bytes\n", flash, flash + size[".vector_table"]
        printf "RAM: .data + .bss = %d bytes (.uninit: %d)\n", size[".data"] + size[".bss"], size[".uninit"]
    }'

# With LTO most of the core is inlined into the scene's render loop, so symbol names undercount it. The line
# table says which source file each half-word of .text came from: code from Rust's core library is charged to
# the innermost caller outside it (addr2line -i), so `f32::is_finite` inlined into the rasterizer counts as the
# rasterizer's.
echo "== arm-none-eabi-addr2line -a -i -e $elf, every half-word of .text: bytes of code by source crate"
read -r text_start text_size < <(arm-none-eabi-size -A "$elf" | awk '$1 == ".text" { print $3, $2 }')
seq "$text_start" 2 $((text_start + text_size - 2)) | awk '{ printf "%x\n", $1 }' |
    arm-none-eabi-addr2line -a -i -e "$elf" | awk -F: '
    function crate(f) {
        if (f ~ /\/library\/core\//) return "Rust core library (formatting...)"
        if (f ~ /\/core\/src\//) return "rastty-core"
        if (f ~ /\/firmware\/scene\//) return "rastty-firmware-scene"
        if (f ~ /\/firmware\/src\//) return "rastty-firmware"
        if (f ~ /\/embedded\/src\//) return "rastty-embedded-graphics"
        if (f ~ /\/embedded-graphics-core-/) return "embedded-graphics-core"
        if (f ~ /\/libm-/) return "libm"
        if (f ~ /compiler.builtins/) return "compiler-builtins (f64 soft-float, memcpy, u64 division)"
        if (f ~ /\/cortex-m/) return "cortex-m, cortex-m-rt, cortex-m-semihosting"
        return "no line information (assembly)"
    }
    function flush() { if (have) bytes[owner != "" ? owner : first] += 2 }
    /^0x/ { flush(); have = 1; first = ""; owner = ""; next }
    {
        c = crate($1)
        if (first == "") first = c
        if (owner == "" && c !~ /^Rust core library/) owner = c
    }
    END { flush(); for (c in bytes) printf "%8d  %s\n", bytes[c], c }' | sort -rn

echo "== arm-none-eabi-nm -S -t d -C $elf: bytes of .rodata by symbol"
read -r rodata_start rodata_size < <(arm-none-eabi-size -A "$elf" | awk '$1 == ".rodata" { print $3, $2 }')
arm-none-eabi-nm -S -t d -C "$elf" | awk -v start="$rodata_start" -v size="$rodata_size" '
    NF >= 4 && $1 + 0 >= start && $1 + 0 < start + size {
        if ($4 ~ /^rastty_firmware_scene::spot::/) model += $2
        else if ($4 ~ /^libm::/) libm += $2
    }
    END {
        printf "%8d  the model arrays (rastty_firmware_scene::spot)\n", model
        printf "%8d  libm tables\n", libm
        printf "%8d  the rest: unnamed constants (strings, panic locations, lookup tables) of every crate, padding\n",
            size - model - libm
    }'

echo "== qemu-system-arm -cpu cortex-m4 -machine mps2-an386 -nographic -semihosting-config enable=on,target=native" \
    "-icount shift=0 -kernel $elf"
timeout 300 qemu-system-arm -cpu cortex-m4 -machine mps2-an386 -nographic \
    -semihosting-config enable=on,target=native -icount shift=0 -kernel "$elf" | tee "$out"

echo "== estimate: the frame rate at 168 MHz, assuming 1 instruction per cycle (a Cortex-M4 often needs more);" \
    "the model's triangles and the shaded fragments per million instructions"
awk '
    match($0, /[0-9]+x[0-9]+ RGB565/) { split(substr($0, RSTART, RLENGTH - 7), wh, "x"); pixels = wh[1] * wh[2] }
    match($0, /Spot \([0-9]+ vertices, [0-9]+ triangles/) { split(substr($0, RSTART, RLENGTH), w, " "); triangles = w[4] }
    /^frame [0-9]+ in [0-9]+ KiB: [0-9]+ instructions/ {
        match($0, /\([a-z]+: [0-9]+ fragments\)/)
        split(substr($0, RSTART + 1, RLENGTH - 2), f, " ")
        printf "%s %s in %s KiB, %s %d instructions, %.1f per pixel: %.2f frames per second, %.1f ms per frame; " \
            "%.0f triangles and %.0f fragments per million instructions\n",
            $1, $2, $4, f[1], $6, $6 / pixels, 168e6 / $6, $6 / 168e3, triangles * 1e6 / $6, f[2] * 1e6 / $6
    }' "$out"

if [ "$stages" = 1 ]; then
    # Each frame is drawn twice: timed, then checked with its depths.
    renders=$((2 * $(grep -cE '^frame [0-9]+ in [0-9]+ KiB: checksum' "$out")))
    echo "== instructions by stage over the run's $renders renders: qemu-system-arm ... -d in_asm,exec,nochain," \
        "read by stages.py"
    mkfifo "$pipe"
    python3 stages.py "$elf" "$pipe" "$renders" &
    reader=$!
    timeout 900 qemu-system-arm -cpu cortex-m4 -machine mps2-an386 -nographic \
        -semihosting-config enable=on,target=native -icount shift=0 -d in_asm,exec,nochain -D "$pipe" \
        -kernel "$elf" >/dev/null
    wait "$reader"
fi
