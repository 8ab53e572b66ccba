#include "roadscale/pipeline/stage_thread.h"

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace roadscale {
namespace {

std::string MessageOf(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return e.what();
  }
}

TEST(StageThread, KeepsTheErrorAndRunsItsHandlersOnItsOwnThread) {
  std::atomic<bool> error_handled{false};
  std::atomic<bool> exited{false};
  StageThread stage([] { throw std::runtime_error("frame 7: corrupt"); },
                    [&] { error_handled = true; }, [&] { exited = true; });
  const std::exception_ptr error = stage.Join();
  ASSERT_TRUE(error);
  EXPECT_EQ(MessageOf(error), "frame 7: corrupt");
  EXPECT_TRUE(error_handled);
  EXPECT_TRUE(exited);
}

TEST(StageThread, AStageThatEndsWellHasNoErrorAndStillExits) {
  std::atomic<bool> error_handled{false};
  std::atomic<bool> exited{false};
  StageThread stage([] {}, [&] { error_handled = true; }, [&] { exited = true; });
  EXPECT_FALSE(stage.Join());
  EXPECT_FALSE(error_handled);
  EXPECT_TRUE(exited);
}

TEST(StageThread, AQueueStageHandsOnEveryItemInOrderThenClosesItsOutput) {
  BoundedQueue<int> in(2);
  BoundedQueue<std::string> out(2);
  const std::unique_ptr<StageThread> stage =
      StartQueueStage(in, out, [](int value) { return std::to_string(value * 10); });
  StageThread producer(
      [&] {
        for (int value = 1; value <= 5; ++value) in.Push(value);
      },
      [] {}, [&] { in.Close(); });
  std::vector<std::string> received;
  while (std::optional<std::string> item = out.Pop()) received.push_back(*item);
  EXPECT_EQ(received, (std::vector<std::string>{"10", "20", "30", "40", "50"}));
  EXPECT_FALSE(stage->Join());
  EXPECT_FALSE(producer.Join());
}

TEST(StageThread, AnErrorInAQueueStageStopsTheStageBeforeItAndEndsTheOneAfterIt) {
  BoundedQueue<int> in(1);
  BoundedQueue<int> out(1);
  const std::unique_ptr<StageThread> stage = StartQueueStage(in, out, [](int value) {
    if (value == 3) throw std::runtime_error("bad frame 3");
    return value;
  });
  std::atomic<bool> producer_refused{false};
  // Without the cancel, this producer would wait for room forever.
  StageThread producer(
      [&] {
        for (int value = 1; value <= 1000; ++value) {
          if (!in.Push(value)) {
            producer_refused = true;
            return;
          }
        }
      },
      [] {}, [&] { in.Close(); });
  std::vector<int> received;
  while (std::optional<int> item = out.Pop()) received.push_back(*item);
  EXPECT_EQ(received, (std::vector<int>{1, 2}));
  const std::exception_ptr error = stage->Join();
  ASSERT_TRUE(error);
  EXPECT_EQ(MessageOf(error), "bad frame 3");
  EXPECT_FALSE(producer.Join());
  EXPECT_TRUE(producer_refused);
}

TEST(StageThread, TheFinalStageReturnsItsErrorAfterItsHandler) {
  bool handled = false;
  const std::exception_ptr error =
      RunFinalStage([] { throw std::runtime_error("cannot write"); }, [&] { handled = true; });
  ASSERT_TRUE(error);
  EXPECT_EQ(MessageOf(error), "cannot write");
  EXPECT_TRUE(handled);
  EXPECT_FALSE(RunFinalStage([] {}, [&] { handled = false; }));
  EXPECT_TRUE(handled);
}

TEST(StageThread, RethrowsTheFirstErrorGiven) {
  const std::exception_ptr none;
  const std::exception_ptr late = std::make_exception_ptr(std::runtime_error("late stage"));
  const std::exception_ptr early = std::make_exception_ptr(std::runtime_error("early stage"));
  EXPECT_NO_THROW(RethrowFirstError({none, none}));
  try {
    RethrowFirstError({none, late, early});
    FAIL() << "no error rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "late stage");
  }
}

}  // namespace
}  // namespace roadscale
