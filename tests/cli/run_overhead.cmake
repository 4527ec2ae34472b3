# scripts/run on an up-to-date build against the bare executable on the same deck: both times
# are REPORTED (message lines; `ctest -V -R cli.run_overhead` shows them), never asserted. What
# is asserted: scripts/run's fast path runs the program without building and writes the same
# files as the bare executable (HDF5 bit for bit, listing and summary but for the timing lines);
# it writes to out/ without -o; its up-to-date test (pound_program_current) turns false when a
# source, a folder of src/ or CMakeLists.txt is newer than the program; usage errors exit 2.
#
# The fast path is run in a copy of the scripts beside a stand-in tree (src/, cmake/,
# CMakeLists.txt dated 2020, build/release/pound a copy of the program under test): a test
# never runs cmake on the tree whose build is being tested. scripts/run of the source tree is
# run with POUND_EXE (which it runs without building) for the out/ default.
include(${CMAKE_CURRENT_LIST_DIR}/common.cmake.inc)
set(deck ${SOURCE_DIR}/input/two_frames_elastic.nml)
set(tree ${WORK_DIR}/tree)
file(MAKE_DIRECTORY ${tree}/scripts ${tree}/src/core ${tree}/cmake ${tree}/build/release)
file(COPY ${SOURCE_DIR}/scripts/run ${SOURCE_DIR}/scripts/lib.sh DESTINATION ${tree}/scripts)
file(WRITE ${tree}/src/core/stand_in.f90 "! a source of the stand-in tree\n")
file(WRITE ${tree}/cmake/stand_in.cmake "# stand-in\n")
file(WRITE ${tree}/CMakeLists.txt "# stand-in: scripts/run must not configure this tree\n")
file(COPY ${POUND_EXE} DESTINATION ${tree}/build/release)
get_filename_component(exe_name ${POUND_EXE} NAME)
if(NOT exe_name STREQUAL "pound")
  file(RENAME ${tree}/build/release/${exe_name} ${tree}/build/release/pound)
endif()
run_shell(t "touch -d 2020-01-01 tree/src/core/stand_in.f90 tree/src/core tree/src tree/cmake/stand_in.cmake tree/cmake tree/CMakeLists.txt && touch tree/build/release/pound")
expect_equal("dating the stand-in tree" 0 "${t_rc}")

# Interleaved runs, 5 each: the bare program, then scripts/run's fast path (no POUND_EXE).
set(ENV{DECK} "${deck}")
run_shell(b [=[
set -e
n=5; bare=(); run=(); diff=()
for i in $(seq $n); do
  t0=$(date +%s%N); "$POUND" "$DECK" -o bare > bare.stdout; t1=$(date +%s%N)
  env -u POUND_EXE tree/scripts/run "$DECK" -o viarun > viarun.stdout 2> viarun.stderr; t2=$(date +%s%N)
  bare+=($(( (t1 - t0) / 1000 ))); run+=($(( (t2 - t1) / 1000 ))); diff+=($(( (t2 - t1 - t1 + t0) / 1000 )))
done
med() { printf '%s\n' "$@" | sort -n | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
printf 'bare executable: median %.1f ms; scripts/run (up to date): median %.1f ms; scripts/run - bare: median %.1f ms (%d interleaved runs each)\n' \
  "$(med "${bare[@]}")e-3" "$(med "${run[@]}")e-3" "$(med "${diff[@]}")e-3" $n
]=])
message(STATUS "run_overhead: ${b_out}")
expect_equal("timed runs: exit status (stderr: ${b_err})" 0 "${b_rc}")
file(READ ${WORK_DIR}/viarun.stderr run_err)
string(FIND "${run_err}" "build" pos)
if(NOT pos EQUAL -1)
  message(FATAL_ERROR "scripts/run on an up-to-date build built something:\n${run_err}")
endif()
expect_published(bare two_frames_elastic)
expect_published(viarun two_frames_elastic)

# The same files. HDF5: bit for bit but the timing attributes (scripts/h5_compare.py).
execute_process(COMMAND /usr/bin/python3 ${SOURCE_DIR}/scripts/h5_compare.py
                        bare/two_frames_elastic.h5 viarun/two_frames_elastic.h5
                WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE c_rc OUTPUT_VARIABLE c_out ERROR_VARIABLE c_err)
expect_equal("HDF5 of scripts/run against the bare executable: ${c_out}${c_err}" 0 "${c_rc}")
# Listing and standard output: equal once the lines with the date and wall-clock timings go.
run_shell(l [=[
untimed() { grep -v -E 'run on |integration|time:|elapsed|written during|[0-9] s\)? *$|seconds' "$1" | sed 's#viarun/#bare/#g'; }
diff <(untimed bare/two_frames_elastic.out) <(untimed viarun/two_frames_elastic.out) >&2 || exit 1
diff <(untimed bare.stdout) <(untimed viarun.stdout) >&2 || exit 2
test "$(untimed bare.stdout | wc -c)" -ge 200 || exit 3
test "$(untimed bare/two_frames_elastic.out | wc -l)" -ge 200 || exit 4
]=])
if(NOT l_rc EQUAL 0)
  message(FATAL_ERROR "listing (1), standard output (2) of scripts/run against the bare executable, "
                      "or too short (3, 4): status ${l_rc}\n${l_err}")
endif()

# The up-to-date test turns false for a newer source, a new file in src/ and CMakeLists.txt.
run_shell(s [=[
source tree/scripts/lib.sh
check() { if pound_program_current tree/build/release/pound; then echo "$1: current"; else echo "$1: stale"; fi; }
check "as built"
touch tree/src/core/stand_in.f90; check "source touched"
touch -d 2020-01-01 tree/src/core/stand_in.f90; check "source dated back"
touch tree/src/core/new.f90; check "file added"
rm tree/src/core/new.f90; touch -d 2020-01-01 tree/src/core; check "file removed, folder dated back"
touch tree/CMakeLists.txt; check "CMakeLists.txt touched"
touch -d 2020-01-01 tree/CMakeLists.txt; rm tree/build/release/pound; check "no program"
]=])
expect_equal("up-to-date test (stderr: ${s_err})"
  "as built: current\nsource touched: stale\nsource dated back: current\nfile added: stale\nfile removed, folder dated back: current\nCMakeLists.txt touched: stale\nno program: stale\n"
  "${s_out}")

# scripts/run of the source tree with POUND_EXE: no build; outputs in out/ without -o.
run_shell(o "POUND_EXE='${POUND_EXE}' '${SOURCE_DIR}/scripts/run' '${deck}'")
expect_equal("scripts/run without -o: exit status (stderr: ${o_err})" 0 "${o_rc}")
expect_published(out two_frames_elastic)
run_shell(u "'${SOURCE_DIR}/scripts/run'")
expect_equal("scripts/run without a deck: exit status" 2 "${u_rc}")
expect_contains("scripts/run without a deck" "${u_err}" "usage: scripts/run DECK.nml")
