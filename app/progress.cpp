#include "app/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace hullopt::app {

std::string FormatDuration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  char buf[32];
  const long t = std::lround(s);
  if (t >= 3600) {
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t % 3600) / 60);
  } else if (t >= 60) {
    std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  } else {
    std::snprintf(buf, sizeof buf, "%lds", t);
  }
  return buf;
}

Progress::Progress(std::string label, long total, bool enabled)
    : label_(std::move(label)),
      total_(std::max(1L, total)),
      enabled_(enabled),
      tty_(::isatty(STDERR_FILENO) != 0) {
  start_ = last_draw_ = std::chrono::steady_clock::now();
}

std::string Progress::Line(long done, long replayed) const {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const long computed = done - replayed;
  const double rate = elapsed > 0 ? computed / elapsed : 0.0;
  const double eta = rate > 0 ? (total_ - done) / rate : NAN;
  char buf[160];
  std::snprintf(buf, sizeof buf, "%ld/%ld evaluations (%.0f%%), %.3g eval/s, elapsed %s, ETA %s", done,
                total_, 100.0 * std::min(1.0, static_cast<double>(done) / total_), rate,
                FormatDuration(elapsed).c_str(), FormatDuration(eta).c_str());
  std::string s = buf;
  if (replayed > 0) s += ", " + std::to_string(replayed) + " replayed from the log";
  return s;
}

void Progress::Update(long done, long replayed) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (tty_) {
    if (now - last_draw_ < std::chrono::milliseconds(100) && done < total_) return;
    last_draw_ = now;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(kWidth * std::min(1.0, static_cast<double>(done) / total_));
    std::string bar(filled, '#');
    bar += std::string(kWidth - filled, '.');
    std::fprintf(stderr, "\r%s [%s] %s\033[K", label_.c_str(), bar.c_str(), Line(done, replayed).c_str());
    std::fflush(stderr);
  } else {
    const int decile = static_cast<int>(10.0 * std::min(1.0, static_cast<double>(done) / total_));
    if (decile == last_decile_ && now - last_draw_ < std::chrono::seconds(30)) return;
    last_decile_ = decile;
    last_draw_ = now;
    std::fprintf(stderr, "%s: %s\n", label_.c_str(), Line(done, replayed).c_str());
    std::fflush(stderr);
  }
}

void Progress::Finish(long done, long replayed) {
  if (!enabled_) return;
  if (tty_) std::fprintf(stderr, "\r\033[K");
  std::fprintf(stderr, "%s: done, %s\n", label_.c_str(), Line(done, replayed).c_str());
  std::fflush(stderr);
}

}  // namespace hullopt::app
