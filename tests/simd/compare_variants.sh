#!/usr/bin/env bash
# simd_generic_path (tests/CMakeLists.txt): the element pass's hash from the program built as the
# solver is and from the one built with the batched kernels for generic x86-64 only must agree.
#   compare_variants.sh DISPATCHED GENERIC
set -u
a=$("$1") || { echo "FAIL: $1 did not run"; exit 1; }
b=$("$2") || { echo "FAIL: $2 did not run"; exit 1; }
echo "as built:      $a"
echo "generic only:  $b"
[ -n "${a%% *}" ] && [ "${a%% *}" = "${b%% *}" ] || { echo "FAIL: the two variants differ"; exit 1; }
echo "simd_generic_path: the same bits"
