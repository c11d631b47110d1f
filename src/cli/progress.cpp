#include "cli/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace aapat {
namespace {
bool g_lines = false;
bool g_quiet = false;

// The seconds between two lines off a terminal: kProgressLineSeconds, or
// AAPAT_PROGRESS_SECONDS (a number >= 0; 0 prints every update, as a test of
// a short command does).
double line_seconds() {
  if (const char* v = std::getenv("AAPAT_PROGRESS_SECONDS")) {
    char* end = nullptr;
    const double s = std::strtod(v, &end);
    if (end != v && *end == '\0' && s >= 0 && s < 1e6) return s;
  }
  return kProgressLineSeconds;
}
}  // namespace

void Progress::print_lines(bool on) {
  g_lines = on;
}

bool Progress::printing_lines() {
  return g_lines;
}

void Progress::quiet(bool on) {
  g_quiet = on;
}

bool Progress::quieted() {
  return g_quiet;
}

Progress::Progress(std::string label)
    : label_(std::move(label)),
      style_(g_quiet            ? Style::kNone
             : g_lines          ? Style::kTenths
             : ::isatty(2) == 1 ? Style::kBar
                                : Style::kTimedLines),
      start_(std::chrono::steady_clock::now()),
      last_line_(start_) {}

Progress::~Progress() {
  if (style_ == Style::kBar && drawn_) std::fputs("\n", stderr);
}

void Progress::update(int done, int total, const std::string& note) {
  if (total <= 0 || style_ == Style::kNone) return;
  const auto line = [&] {
    std::fputs(fmt::format("{}: {}/{} {}\n", label_, done, total, note).c_str(), stderr);
    std::fflush(stderr);
  };
  if (style_ == Style::kTenths) {
    const int tenths = done * 10 / total;
    if (tenths == tenths_) return;
    tenths_ = tenths;
    line();
    return;
  }
  if (style_ == Style::kTimedLines) {
    const auto now = std::chrono::steady_clock::now();
    const std::chrono::duration<double> since = now - last_line_;
    if (since.count() < line_seconds()) return;
    last_line_ = now;
    line();
    return;
  }
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
