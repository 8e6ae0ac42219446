# Sourced by sanitize.sh and fuzz.sh: the one sanitized build both use (clang, ASan + UBSan, every
# target including the UI and the libFuzzer targets, but not the benchmarks, which it never runs),
# so CI compiles it once. -O1 with line tables only: what ASan's reports and the leak suppressions need
# (function names, files and lines, inlined frames too), at a fraction of -O2 -g's compile time.
sanitized_build="${SORTIE_ASAN_BUILD_DIR:-build-asan}"

configure_sanitized_build() {
  CC=clang CXX=clang++ cmake -S . -B "$sanitized_build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
    -DSORTIE_SANITIZE=ON -DSORTIE_FUZZ=ON -DSORTIE_BUILD_UI=ON -DBUILD_TESTING=ON -DSORTIE_BUILD_BENCHMARKS=OFF \
    -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link" >/dev/null
}

# The LeakSanitizer suppressions (tests/sanitizers/lsan.supp) match function names, so every report
# must be symbolized: without llvm-symbolizer they match nothing and the Qt Quick tests fail on leaks
# inside Qt. Finds the symbolizer of the clang that builds (llvm-<major>, installed by install-deps.sh),
# else any on PATH, exports it for ASan/LSan/UBSan, and stops at once with what to install when none.
require_symbolizer() {
  local major candidate
  major=$(clang -dumpversion 2>/dev/null || echo 14)
  major=${major%%.*}
  for candidate in "${ASAN_SYMBOLIZER_PATH:-}" "/usr/lib/llvm-$major/bin/llvm-symbolizer" \
                   "$(command -v "llvm-symbolizer-$major" || true)" "$(command -v llvm-symbolizer || true)"; do
    if [ -n "$candidate" ] && [ -x "$candidate" ]; then
      export ASAN_SYMBOLIZER_PATH="$candidate" UBSAN_SYMBOLIZER_PATH="$candidate"
      echo "sanitizers: symbolizing with $candidate"
      return 0
    fi
  done
  echo "sanitizers: no llvm-symbolizer found (looked for /usr/lib/llvm-$major/bin/llvm-symbolizer," \
       "llvm-symbolizer-$major and llvm-symbolizer on PATH). The leak suppressions match function names and" \
       "need it: install the Debian package llvm-$major (scripts/install-deps.sh does) or set" \
       "ASAN_SYMBOLIZER_PATH." >&2
  exit 2
}
