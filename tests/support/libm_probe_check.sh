#!/bin/sh
# Usage: libm_probe_check.sh LIBM_PROBE
# Passes when libm_probe prints another hash with FMA and AVX2 masked by GLIBC_TUNABLES, that is
# when the golden_cpu.* runs really use glibc's SSE2 builds. Skips (77) on a CPU without FMA.
grep -qw fma /proc/cpuinfo || exit 77
native=$(env -u GLIBC_TUNABLES "$1") || exit 1
masked=$(GLIBC_TUNABLES=glibc.cpu.hwcaps=-AVX2,-FMA "$1") || exit 1
echo "native $native, FMA and AVX2 masked $masked"
test "$native" != "$masked"
