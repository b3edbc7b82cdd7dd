// How firn chooses how idle OpenMP threads wait (engine/openmp_wait.hpp): the runnable count read
// from /proc/loadavg's text, and the choice to spin only where other tasks leave the cores its
// threads need.
#include <gtest/gtest.h>

#include <cstdlib>

#include "engine/openmp_wait.hpp"

namespace firn {
namespace {

TEST(OpenMPWait, ReadsTheRunnableCountOfLoadavg) {
  EXPECT_EQ(runnable_tasks("0.39 0.33 0.16 1/234 5678\n"), 1);
  EXPECT_EQ(runnable_tasks("12.00 11.50 9.25 17/1024 99"), 17);
  EXPECT_EQ(runnable_tasks(""), -1);
  EXPECT_EQ(runnable_tasks("not a loadavg"), -1);
}

TEST(OpenMPWait, SpinsOnlyWhereTheOtherTasksLeaveTheThreadsTheirCores) {
  EXPECT_TRUE(spin_while_waiting(0, 2, 2));   // alone on two cores
  EXPECT_FALSE(spin_while_waiting(1, 2, 2));  // another task on one of them
  EXPECT_TRUE(spin_while_waiting(1, 2, 1));   // one thread beside it
  EXPECT_TRUE(spin_while_waiting(3, 16, 8));  // a busy task or three on a large machine
  EXPECT_FALSE(spin_while_waiting(9, 16, 8));
  EXPECT_FALSE(spin_while_waiting(-1, 2, 2));  // unreadable: assume a shared machine
}

TEST(OpenMPWait, ReportsItsOwnChoiceElseTheEnvironments) {
  unsetenv("GOMP_SPINCOUNT");
  setenv("OMP_WAIT_POLICY", "passive", 1);  // as the unit tests run (tests/CMakeLists.txt)
  EXPECT_EQ(openmp_wait(), "passive");
  setenv("GOMP_SPINCOUNT", "42", 1);
  EXPECT_EQ(openmp_wait(), "spin:42");
  record_openmp_wait("spin:10000");
  EXPECT_EQ(openmp_wait(), "spin:10000");
  record_openmp_wait("");
  unsetenv("GOMP_SPINCOUNT");
  EXPECT_EQ(openmp_wait(), "passive");
}

}  // namespace
}  // namespace firn
