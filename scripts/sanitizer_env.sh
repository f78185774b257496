# Sourced by scripts/sanitize.sh and scripts/fuzz.sh: the environment both run the asan
# preset's binaries under. ASAN_OPTIONS is each script's own (set before sourcing).
#
# Stack traces with file:line need llvm-symbolizer (package llvm-14).
if [ -x /usr/lib/llvm-14/bin/llvm-symbolizer ]; then
    export ASAN_SYMBOLIZER_PATH=/usr/lib/llvm-14/bin/llvm-symbolizer
fi
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}"
# Leaks inside third-party libraries that are not ours to fix (see the file).
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$PWD/fuzz/lsan.supp:print_suppressions=0}"
