#include "aapat/core/warning.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace aapat {
namespace {

TEST(Warning, GoesToTheHandlerAndBackToStderr) {
  std::vector<std::string> seen;
  const WarningHandler before =
      set_warning_handler([&](const std::string& m) { seen.push_back(m); });
  warn("one");
  warn("two");
  set_warning_handler(before);
  EXPECT_EQ(seen, (std::vector<std::string>{"one", "two"}));
  ::testing::internal::CaptureStderr();
  warn("three");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "aapat: warning: three\n");
}

}  // namespace
}  // namespace aapat
