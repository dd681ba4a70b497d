#!/usr/bin/env bash
# Every test: install what is missing, build, run ctest (under Xvfb when there is no display):
# all tests in VTK's default windows, the rendering tests (label gl) again in single-sampled
# windows, the unit, bad-input, stability, scene and composite tests again under Address- and
# UndefinedBehaviorSanitizer, then the ParaView plugin's tests (scripts/test-paraview.sh: it
# swaps Debian's VTK packages for ParaView's and back; RF_SKIP_PARAVIEW=1 leaves it out).
# Extra arguments go to ctest (for example -L unit). The stability table the stability tests
# write is printed after the runs, then the counts of the four runs as the closing lines
# (the last: "sanitizers: N passed, 0 failed").
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
cd build
table=Testing/stability/stability.md
log=Testing/last-run.log
mkdir -p Testing
rm -f "$table"
runner=()
if [ -z "${DISPLAY:-}" ]; then
  # -noreset: by default Xvfb resets when its last client disconnects, and a client that
  # connects during the reset is refused; VTK then aborts ("bad X server connection").
  # Back-to-back clients hit that window often (54 of 300 short clients here; 0 with
  # -noreset). The project's own GL tests render through EGL and need no X server; Xvfb stays
  # for tests that open X windows.
  runner=(xvfb-run -a -s "-screen 0 1280x1024x24 -noreset")
fi
single_log=Testing/last-run-single-sampled.log
set +e
# Every test in VTK's default window (multisampled), then the rendering tests (label gl) again
# in single-sampled windows: a pass can break either way (the scene capture did, in the first).
"${runner[@]}" ctest --output-on-failure "$@" 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
echo
echo "The rendering tests (label gl) again with RF_TEST_MULTISAMPLES=0 (single-sampled windows):"
RF_TEST_MULTISAMPLES=0 "${runner[@]}" ctest --output-on-failure -L gl "$@" 2>&1 | tee "$single_log"
single_status=${PIPESTATUS[0]}
# The unit, bad-input, stability, scene and composite tests again, built by clang with
# AddressSanitizer and UndefinedBehaviorSanitizer (the module, the reference filters, the
# viewer's code, the tests and the C core; VTK and Mesa are not instrumented): a malformed
# mesh or file must not make this project's code read or write out of bounds or do anything
# undefined. Leak checks are off (VTK and Mesa keep allocations to exit); any undefined
# behaviour aborts its test. The code also carries libFuzzer's coverage (fuzzer-no-link), so
# that the bounded fuzz runs among them (label fuzz: the C core, meshes through the pass's
# CPU-side code, files through the viewer's readers) are guided through all of it. Only the
# programs those tests run are built (scripts/test-programs.py reads them from the test files
# CMake wrote; the C core's fuzzer is a custom target of its own).
sanitizer_labels="unit|badinput|stability|scene|composite"
sanitizer_log=Testing/last-run-sanitizers.log
echo
echo "The $sanitizer_labels tests again under AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/):"
(
  set -euo pipefail
  cd ..
  flags="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined"
  flags="$flags -fno-omit-frame-pointer"
  # A folder configured by another compiler (an older gcc build-asan) is configured anew.
  if [ -f build-asan/CMakeCache.txt ] &&
    ! grep -q "^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++" build-asan/CMakeCache.txt; then
    rm -rf build-asan
  fi
  # C programs link the C++ part of UndefinedBehaviorSanitizer's runtime too, and the C++
  # library it needs: the libraries they use are C++ (-fsanitize-link-c++-runtime, -lstdc++;
  # in the linker flags, so that CMake's own check of the compiler links the same way).
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined -fsanitize-link-c++-runtime -lstdc++" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" >/dev/null
  mapfile -t targets < <(python3 scripts/test-programs.py build-asan "$sanitizer_labels" \
    'badinput\.fuzz_core$')
  [ ${#targets[@]} -gt 0 ] || { echo "no tests labelled $sanitizer_labels" >&2; exit 1; }
  targets+=(fuzz_core_libfuzzer)
  cd build-asan
  cmake --build . -j "$(nproc)" --target "${targets[@]}" >/dev/null
  ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 "${runner[@]}" \
    ctest --output-on-failure -L "$sanitizer_labels" "$@"
) 2>&1 | tee "$sanitizer_log"
sanitizer_status=${PIPESTATUS[0]}
# The ParaView plugin, in ParaView itself (label paraview).
paraview_log=Testing/last-run-paraview.log
echo
echo "The ParaView plugin's tests (paraview/build-and-test.sh):"
(cd .. && bash scripts/test-paraview.sh "$@") 2>&1 | tee "$paraview_log"
paraview_status=${PIPESTATUS[0]}
set -e
if [ -f "$table" ]; then
  echo
  cat "$table"
fi
# ctest: "100% tests passed, 0 tests failed out of 59" -> "59 passed, 0 failed"
summarize() {
  local file=$1 what=$2 summary failed total skipped
  summary=$(grep -E "tests passed, [0-9]+ tests failed out of [0-9]+" "$file" | tail -n 1 || true)
  if [ -n "$summary" ]; then
    failed=$(echo "$summary" | sed -E 's/.* ([0-9]+) tests failed out of ([0-9]+).*/\1/')
    total=$(echo "$summary" | sed -E 's/.* ([0-9]+) tests failed out of ([0-9]+).*/\2/')
    skipped=$(grep -cE "^[[:space:]]+[0-9]+ - .* \(Skipped\)$" "$file" || true)
    echo "ctest, $what: $((total - failed - skipped)) passed, $failed failed, $skipped skipped"
  fi
}
echo
summarize "$single_log" "rendering tests in single-sampled windows"
summarize "$log" "all tests in VTK's default windows"
if grep -q "paraview stage: skipped" "$paraview_log"; then
  echo "ctest, ParaView plugin: skipped (RF_SKIP_PARAVIEW=1)"
else
  paraview=$(summarize "$paraview_log" "ParaView plugin")
  if [ -n "$paraview" ]; then
    echo "$paraview"
  elif grep -q "No tests were found" "$paraview_log"; then
    echo "ctest, ParaView plugin: no test selected by the arguments"
  else
    echo "ctest, ParaView plugin: no result (see build/$paraview_log)"
    [ "$paraview_status" -ne 0 ] || paraview_status=1
  fi
fi
sanitizers=$(summarize "$sanitizer_log" "sanitizers")
if [ -n "$sanitizers" ]; then
  echo "${sanitizers#ctest, }" | sed -E 's/, [0-9]+ skipped$//'
else
  echo "sanitizers: no result (see build/$sanitizer_log)"
fi
if [ "$status" -eq 0 ]; then
  status=$single_status
fi
if [ "$status" -eq 0 ]; then
  status=$sanitizer_status
fi
if [ "$status" -eq 0 ]; then
  status=$paraview_status
fi
exit "$status"
