#!/usr/bin/env bash
# Two runs writing the same stem into one folder at the same time, 20 rounds (see
# files_concurrent.cmake). Usage: files_concurrent.sh POUND SOURCE_DIR WORK_DIR
set -u
pound=$1 src=$2 work=$3
cd "$work" || exit 1
mkdir -p d1 d2 res
for k in 1 2; do
  sed -e "s/^   title = .*/   title = 'Deck d$k study'/" -e 's/^   t_end = 5.0 /   t_end = 1.0 /' \
    "$src/input/two_frames_pdelta.nml" >"d$k/run.nml"
done
fail() { echo "round $round: $*" >&2; exit 1; }
for round in $(seq 1 20); do
  "$pound" d1/run.nml -o res >out1 2>err1 &
  p1=$!
  "$pound" d2/run.nml -o res >out2 2>err2 &
  p2=$!
  wait $p1; rc1=$?
  wait $p2; rc2=$?
  for k in 1 2; do
    rc=$([ $k = 1 ] && echo $rc1 || echo $rc2)
    case $rc in
      0) ;;
      1) [ "$(wc -l <err$k)" = 1 ] && grep -q '^pound: error: ' err$k || fail "run $k failed unclearly: $(cat err$k)" ;;
      *) fail "run $k ended with status $rc: $(cat err$k)" ;;
    esac
  done
  [ "$rc1" = 0 ] || [ "$rc2" = 0 ] || fail "both runs failed"
  ls res/.*.partial >/dev/null 2>&1 && fail "partial files left: $(ls -a res)"
  [ -f res/run.out ] && [ -f res/run.h5 ] || fail "incomplete set: $(ls -a res)"
  title=$(sed -n 's/^title: //p' res/run.out)
  case $title in
    'Deck d1 study') other='Deck d2 study' ;;
    'Deck d2 study') other='Deck d1 study' ;;
    *) fail "listing title '$title'" ;;
  esac
  grep -q "deck:  d${title:6:1}/run.nml" res/run.out || fail "listing names another deck"
  grep -aq "$title" res/run.h5 || fail "run.h5 does not hold the title '$title' of run.out"
  grep -aq "$other" res/run.h5 && fail "run.h5 holds the other run's title '$other'"
  # Both runs report what they published; the survivor's is in place.
  for k in 1 2; do
    rc=$([ $k = 1 ] && echo $rc1 || echo $rc2)
    [ "$rc" = 0 ] && ! grep -q 'wrote res/run.out and res/run.h5' out$k && fail "run $k summary: $(cat out$k)"
  done
done
echo "20 rounds: every published pair complete and from one run"
