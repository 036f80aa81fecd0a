#!/usr/bin/env bash
# Proof of sameness: the firmware, run under QEMU, and the host compute the same frames.
#
# Builds the firmware, boots it on QEMU's mps2-an386 (Cortex-M4) with -icount shift=0 (so the instruction counts
# it prints are exact), runs the host test tests/tests/firmware_checksum.rs, and fails unless both print the same
# `frame N in B KiB: checksum 0x..., depth 0x..., S bands, F fragments` lines (colour and depth), in the same order, at
# least two of them. Neither side's values are written down anywhere: each run computes both.
#
# Installs nothing: needs qemu-system-arm, and the thumbv7em-none-eabihf target (rustup target add).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
firmware=$root/firmware
elf=$firmware/target/thumbv7em-none-eabihf/release/rastty-firmware
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "check.sh: building the firmware"
(cd "$firmware" && cargo build --release --locked)

echo "check.sh: running it under QEMU"
status=0
timeout 300 qemu-system-arm -cpu cortex-m4 -machine mps2-an386 -nographic \
    -semihosting-config enable=on,target=native -icount shift=0 -kernel "$elf" >"$out/firmware.txt" 2>&1 ||
    status=$?
sed 's/^/  firmware | /' "$out/firmware.txt"
if [ "$status" -ne 0 ]; then
    echo "check.sh: the firmware failed (exit status $status; 124 is the timeout)" >&2
    exit 1
fi

echo "check.sh: computing the host's checksums"
status=0
(cd "$root" && cargo test --locked -p rastty-tests --test integration \
    firmware_checksum::the_firmware_scene_gives_distinct_checksums -- --exact --nocapture) \
    >"$out/host.txt" 2>&1 || status=$?
if [ "$status" -ne 0 ]; then
    cat "$out/host.txt"
    echo "check.sh: the host test failed (exit status $status)" >&2
    exit 1
fi

line='frame [0-9]+ in [0-9]+ KiB: checksum 0x[0-9a-f]{8}, depth 0x[0-9a-f]{8}, [0-9]+ bands, [0-9]+ fragments'
grep -oE "$line" "$out/firmware.txt" >"$out/firmware.lines" || true
grep -oE "$line" "$out/host.txt" >"$out/host.lines" || true
sed 's/^/  host     | /' "$out/host.lines"
frames=$(wc -l <"$out/firmware.lines")
if [ "$frames" -lt 2 ]; then
    echo "check.sh: the firmware printed $frames frame lines, expected at least 2" >&2
    exit 1
fi
if ! diff -u --label host "$out/host.lines" --label firmware "$out/firmware.lines"; then
    echo "check.sh: the firmware's frames differ from the host's" >&2
    exit 1
fi
echo "check.sh: the firmware's $frames checksums equal the host's"
