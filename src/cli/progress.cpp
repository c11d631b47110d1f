#include "cli/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace aapat {
namespace {
bool g_lines = false;
}  // namespace

void Progress::print_lines(bool on) {
  g_lines = on;
}

bool Progress::printing_lines() {
  return g_lines;
}

Progress::Progress(std::string label)
    : label_(std::move(label)), active_(!g_lines && ::isatty(2) == 1) {}

Progress::~Progress() {
  if (active_ && drawn_) std::fputs("\n", stderr);
}

void Progress::update(int done, int total, const std::string& note) {
  if (g_lines && total > 0) {
    const int tenths = done * 10 / total;
    if (tenths == tenths_) return;
    tenths_ = tenths;
    std::fputs(fmt::format("{}: {}/{} {}\n", label_, done, total, note).c_str(), stderr);
    std::fflush(stderr);
    return;
  }
  if (!active_ || total <= 0) return;
  constexpr int kWidth = 30;
  const int filled = done * kWidth / total;
  std::fputs(fmt::format("\r{} [{}{}] {}/{} {}", label_, std::string(filled, '='),
                         std::string(kWidth - filled, ' '), done, total, note)
                 .c_str(),
             stderr);
  std::fflush(stderr);
  drawn_ = true;
}

StudyProgress Progress::callback() {
  return [this](int done, int total, const std::string& note) { update(done, total, note); };
}

}  // namespace aapat
