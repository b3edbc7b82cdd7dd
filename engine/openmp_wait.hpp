// How idle OpenMP threads wait between the step's launches (issue 15; README, "--threads").
// A launch on a team whose threads sleep (OMP_WAIT_POLICY=passive) first wakes them, and a thread
// that finishes early sleeps and is woken again at the end: on 2 vCPUs under KVM that cost the
// snowball pair (some 21 launches a step) 5-13% of its speed and cube_drop 3-8%, against threads
// that spin a while first (GOMP_SPINCOUNT=10000, about 0.1 ms). Threads that spin take the cores
// other processes need, though: beside a process busy on one of the two cores the same spin made
// both 8-13% slower than passive waiting, and a spin of 100,000 halved the pair
// (docs/performance.md). So `firn` spins briefly where the cores its threads need are idle as it
// starts and waits passively otherwise (apps/firn.cpp), unless the user set OMP_WAIT_POLICY or
// GOMP_SPINCOUNT. The variables are libgomp's, which firn links (GCC's OpenMP).
#pragma once

#include <string>

namespace firn {

constexpr int kOpenMPSpinCount = 10000;

// The number of runnable tasks in the text of /proc/loadavg (its fourth field, "runnable/total"),
// or -1 when the text does not parse.
int runnable_tasks(const std::string& loadavg);

// Whether threads should spin: the tasks other than this process that were runnable at every
// reading (`others`) leave at least `threads` of the `cpus` this process may run on.
bool spin_while_waiting(int others, int cpus, int threads);

// How this process's idle OpenMP threads wait, as one word: "spin:N" (GOMP_SPINCOUNT=N),
// "passive" or "active" (OMP_WAIT_POLICY), "libgomp_default"; firn's own choice where it made one
// (record_openmp_wait), else the environment's.
std::string openmp_wait();
void record_openmp_wait(const std::string& choice);

}  // namespace firn
