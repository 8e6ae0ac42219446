# Sourced by sanitize.sh and fuzz.sh: the one sanitized build both use (clang, ASan + UBSan, every
# target including the UI and the libFuzzer targets), so CI compiles it once.
sanitized_build="${SORTIE_ASAN_BUILD_DIR:-build-asan}"

configure_sanitized_build() {
  CC=clang CXX=clang++ cmake -S . -B "$sanitized_build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DSORTIE_SANITIZE=ON -DSORTIE_FUZZ=ON -DSORTIE_BUILD_UI=ON -DBUILD_TESTING=ON \
    -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link" >/dev/null
}
