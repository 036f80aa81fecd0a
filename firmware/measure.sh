#!/usr/bin/env bash
# Measures the firmware for docs/firmware.md:
# - flash (.text + .rodata) and RAM (.data + .bss), from the ELF file (arm-none-eabi-size -A);
# - which crate each byte of .text comes from (arm-none-eabi-addr2line) and what .rodata holds (arm-none-eabi-nm);
# - from a run under QEMU with -icount shift=0 (1 ns of virtual time per instruction): instructions per frame and
#   per pixel in each memory layout, the peak stack, and the frame rate they imply at 168 MHz, an estimate at 1
#   instruction per cycle;
# - with --stages, from a second run logging every translated block and every block executed
#   (-d in_asm,exec,nochain, read through a pipe by stages.py): the instructions of each pipeline stage.
# Needs arm-none-eabi-size, -nm and -addr2line (Debian: binutils-arm-none-eabi), qemu-system-arm and, for --stages,
# python3; check.sh, which CI runs, needs none of them but QEMU.
# Usage: firmware/measure.sh [--no-build] [--stages]
set -euo pipefail
cd "$(dirname "$0")"
elf=target/thumbv7em-none-eabihf/release/rastty-firmware
build=1 stages=0
for arg in "$@"; do
    case $arg in
        --no-build) build=0 ;;
        --stages) stages=1 ;;
        *) echo "usage: $0 [--no-build] [--stages]" >&2; exit 2 ;;
    esac
done
if [ "$build" = 1 ]; then
    cargo build --release --locked
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

echo "== estimate: the frame rate at 168 MHz, assuming 1 instruction per cycle (a Cortex-M4 often needs more)"
awk '
    match($0, /[0-9]+x[0-9]+ RGB565/) { split(substr($0, RSTART, RLENGTH - 7), wh, "x"); pixels = wh[1] * wh[2] }
    /^frame [0-9]+ in [0-9]+ KiB: [0-9]+ instructions/ {
        printf "%s %s in %s KiB: %d instructions, %.1f per pixel: %.2f frames per second, %.1f ms per frame\n",
            $1, $2, $4, $6, $6 / pixels, 168e6 / $6, $6 / 168e3
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
