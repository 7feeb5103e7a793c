#!/usr/bin/env bash
# Coverage-guided fuzzing of the deck reader with libFuzzer (clang), under ASan + UBSan:
#   tools/fuzz_reader.sh [SECONDS]        (default 300)
# Builds build-fuzz/ with clang, seeds the corpus from the public decks and tests/data/fuzz/, and
# runs tests/fuzz/reader_fuzz.cpp's LLVMFuzzerTestOneInput. A failure is kept by libFuzzer as
# build-fuzz/crash-*; replay it with any build: build/tests/mcdyna_reader_fuzz FILE.
# CI runs the same target through its own mutation driver instead (tests/CMakeLists.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-300}
tools/setup.sh
command -v clang++ >/dev/null || { echo "fuzz_reader: needs clang (apt-get install clang)"; exit 2; }
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DMCDYNA_SANITIZE=ON -DMCDYNA_LIBFUZZER=ON >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target mcdyna_reader_fuzz
corpus=build-fuzz/corpus
mkdir -p "$corpus"
find tests/data/public-decks tests/data/fuzz decks -type f \( -name '*.k' -o -name '*.key' -o -name '*.dyn' \) \
  -size -64k -exec cp -n {} "$corpus"/ \;
cd build-fuzz
./tests/mcdyna_reader_fuzz -max_total_time="$seconds" -max_len=65536 -timeout=20 -rss_limit_mb=4096 corpus
