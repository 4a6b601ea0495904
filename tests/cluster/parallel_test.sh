#!/usr/bin/env bash
# GNU parallel, for real: grades a class of 20 in 4 shards with the command of course/grading.md,
# on the "machines" of an sshloginfile (here this one, as `:`, two jobs at a time), merges the
# shard gradebooks and checks that the merged gradebook is the one-machine gradebook.
# Needs the package of tests/cluster/packages.txt:
#   parallel
# else exits 77 (skipped), saying why.
# Usage: parallel_test.sh FROB SOURCE_DIR
frob=$1 source=$2
source "$(dirname "$0")/common.sh"

command -v parallel > /dev/null || skip "no GNU parallel: apt-get install --no-install-recommends parallel (tests/cluster/packages.txt)"
parallel --version 2> /dev/null | grep -q "GNU parallel" || skip "$(command -v parallel) is not GNU parallel (moreutils' parallel?)"
make_work
export PARALLEL_HOME="$work/parallel-home"  # not ~/.parallel
mkdir "$work/bin" && ln -s "$(realpath "$frob")" "$work/bin/frob"  # the command says frob, as on the machines
export PATH="$work/bin:$PATH"

make_class "$source"
grade_one_machine
cd "$work"

start=$SECONDS
echo "2/:" > machines.txt  # `:` is this machine; on a cluster, a line such as 2/node1 per machine
interruptible timeout 240 parallel --will-cite --sshloginfile machines.txt --workdir . --env FROB_CACHE_DIR \
  'frob grade go_to_goal class/ --jobs 1 --shard {}/4 --gradebook grades-{}.csv --visible-only --secret secret.txt' \
  ::: $(seq 4) > parallel.log 2>&1 || { cat parallel.log >&2; fail "parallel: a shard failed"; }
check_shards "$work/grades" 4
echo "GNU parallel graded the class in 4 shards in $((SECONDS - start)) s; merged, the gradebook is the one-machine gradebook"
