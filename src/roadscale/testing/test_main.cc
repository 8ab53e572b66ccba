#include <gtest/gtest.h>

// GoogleTest's own main, but a run in which every selected test was skipped (a test of shared
// data that is not there) exits with 77, which CTest reports as skipped: CTest runs a whole
// suite in one process (cmake/RoadscaleHelpers.cmake), so a skip must show in the exit code.
int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  const int status = RUN_ALL_TESTS();
  const ::testing::UnitTest& tests = *::testing::UnitTest::GetInstance();
  constexpr int kSkipped = 77;
  if (status == 0 && tests.successful_test_count() == 0 && tests.skipped_test_count() > 0) {
    return kSkipped;
  }
  return status;
}
