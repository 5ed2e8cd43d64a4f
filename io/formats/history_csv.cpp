#include "io/formats/history_csv.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "io/formats/input_error.h"

namespace hullopt::io {
namespace {

std::string Exact(double v) {
  if (std::isnan(v)) return "nan";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string Sanitise(const std::string& s) {
  std::string out;
  for (char c : s) out += (c == ',' ? ';' : (c == '\n' || c == '\r' || c == '"') ? ' ' : c);
  return out;
}

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

}  // namespace

std::string HistoryLayout::Header() const {
  std::string h = "evaluation";
  for (const auto& v : variables) h += "," + v;
  h += ",objective,feasible";
  for (const auto& s : seas) h += "," + s;
  for (const auto& q : quantities) h += "," + q;
  h += ",wall_time_s,run,step,message";
  return h;
}

std::string FormatHistoryRow(long evaluation, const opt::EvaluationRecord& rec,
                             const std::vector<double>& reported, const HistoryLayout& layout) {
  const bool produced = rec.result.produced;
  std::string row = std::to_string(evaluation);
  for (double x : rec.x) row += "," + Exact(x);
  row += "," + (produced ? Exact(rec.result.objective) : std::string("nan"));
  row += rec.feasible ? ",1" : ",0";
  for (std::size_t i = 0; i < layout.seas.size(); ++i)
    row += "," + (produced ? Exact(rec.result.sea_values[i]) : std::string("nan"));
  for (std::size_t i = 0; i < layout.quantities.size(); ++i)
    row += "," + (produced ? Exact(reported[i]) : std::string("nan"));
  char wall[32];
  std::snprintf(wall, sizeof wall, "%.6g", rec.wall_time_s);
  row += std::string(",") + wall + "," + std::to_string(rec.run) + "," + std::to_string(rec.step) + "," +
         Sanitise(produced ? (rec.result.warning.empty() ? std::string() : kWarningPrefix + rec.result.warning)
                           : rec.result.error) +
         "\n";
  return row;
}

HistoryRow ParseHistoryRow(const std::string& line, const HistoryLayout& layout, const std::string& where) {
  const std::size_t nv = layout.variables.size(), ns = layout.seas.size(), nq = layout.quantities.size();
  const std::size_t ncols = 1 + nv + 2 + ns + nq + 4;
  const auto f = Split(line);
  auto bad = [&](const std::string& why) {
    throw InputError(where + ": " + why + " (the file is damaged; delete it to start the campaign over)");
  };
  if (f.size() != ncols)
    bad("expected " + std::to_string(ncols) + " columns, found " + std::to_string(f.size()));
  auto num = [&](const std::string& s) {
    char* e = nullptr;
    const double v = std::strtod(s.c_str(), &e);
    if (s.empty() || *e != '\0') bad("'" + s + "' is not a number");
    return v;
  };
  auto integer = [&](const std::string& s) {
    char* e = nullptr;
    const long v = std::strtol(s.c_str(), &e, 10);
    if (s.empty() || *e != '\0') bad("'" + s + "' is not a whole number");
    return v;
  };
  HistoryRow row;
  row.evaluation = integer(f[0]);
  std::size_t c = 1;
  opt::EvaluationRecord& r = row.record;
  // Column names for messages, in column order.
  auto name_of = [&](std::size_t col) -> std::string {
    if (col == 0) return "evaluation";
    if (col <= nv) return layout.variables[col - 1];
    if (col == nv + 1) return "objective";
    if (col == nv + 2) return "feasible";
    if (col <= nv + 2 + ns) return layout.seas[col - nv - 3];
    if (col <= nv + 2 + ns + nq) return layout.quantities[col - nv - 3 - ns];
    const char* tail[] = {"wall_time_s", "run", "step", "message"};
    return tail[col - (nv + 3 + ns + nq)];
  };
  auto column = [&](std::size_t col, const std::string& rule) {
    bad("column '" + name_of(col) + "' = '" + f[col] + "': " + rule);
  };
  for (std::size_t i = 0; i < nv; ++i, ++c) {
    r.x.push_back(num(f[c]));
    if (!std::isfinite(r.x.back())) column(c, "a design variable must be finite");
  }
  const std::size_t objective_col = c;
  r.result.objective = num(f[c++]);
  if (f[c] != "0" && f[c] != "1") column(c, "must be 0 or 1");
  const std::size_t feasible_col = c;
  r.feasible = f[c++] == "1";
  const std::size_t results_begin = c;
  for (std::size_t i = 0; i < ns; ++i) r.result.sea_values.push_back(num(f[c++]));
  for (std::size_t i = 0; i < nq; ++i) row.reported.push_back(num(f[c++]));
  const std::size_t results_end = c;
  r.wall_time_s = num(f[c]);
  if (!(std::isfinite(r.wall_time_s) && r.wall_time_s >= 0)) column(c, "must be a finite time >= 0");
  ++c;
  r.run = static_cast<int>(integer(f[c]));
  if (r.run < -1) column(c, "must be >= -1");
  ++c;
  r.step = static_cast<int>(integer(f[c]));
  if (r.step < 0) column(c, "must be >= 0");
  ++c;
  const std::string& message = f[c++];
  if (message.compare(0, kWarningPrefix.size(), kWarningPrefix) == 0)
    r.result.warning = message.substr(kWarningPrefix.size());
  else
    r.result.error = message;
  r.result.produced = r.result.error.empty();
  // An evaluated design has finite numbers throughout; a refused one (its reason in `message`) has none.
  if (r.result.produced) {
    if (!std::isfinite(r.result.objective)) column(objective_col, "an evaluated design's objective must be finite");
    for (std::size_t k = results_begin; k < results_end; ++k)
      if (!std::isfinite(num(f[k]))) column(k, "an evaluated design's values must be finite");
  } else {
    if (f[objective_col] != "nan") column(objective_col, "a refused design (message set) has objective nan");
    if (r.feasible) column(feasible_col, "a refused design is infeasible (0)");
    for (std::size_t k = results_begin; k < results_end; ++k)
      if (f[k] != "nan") column(k, "a refused design has no values (nan)");
    r.result.sea_values.clear();
    row.reported.clear();
  }
  return row;
}

HistoryLayout ReadHistoryLayout(const std::string& path) {
  std::ifstream in(path);
  std::string header;
  if (!in || !std::getline(in, header)) throw InputError(path + ": missing or empty");
  const std::vector<std::string> c = Split(header);
  const std::vector<std::string> tail{"wall_time_s", "run", "step", "message"};
  std::size_t objective = 1;
  while (objective + 1 < c.size() && !(c[objective] == "objective" && c[objective + 1] == "feasible")) ++objective;
  const std::size_t results_begin = objective + 2;
  if (c[0] != "evaluation" || results_begin + tail.size() > c.size() ||
      !std::equal(tail.begin(), tail.end(), c.end() - static_cast<long>(tail.size())))
    throw InputError(path + ":1: not a history file (columns evaluation, <variables>, objective, feasible, ..., " +
                     "wall_time_s, run, step, message)");
  HistoryLayout layout;
  layout.variables.assign(c.begin() + 1, c.begin() + static_cast<long>(objective));
  layout.quantities.assign(c.begin() + static_cast<long>(results_begin),
                           c.end() - static_cast<long>(tail.size()));
  return layout;
}

HistoryFile ReadHistory(const std::string& path, const HistoryLayout& layout) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return HistoryFile{};
  std::stringstream ss;
  ss << in.rdbuf();
  return ParseHistory(ss.str(), path, layout);
}

HistoryFile ParseHistory(const std::string& text, const std::string& path, const HistoryLayout& layout) {
  HistoryFile out;
  const std::size_t header_end = text.find('\n');
  if (header_end == std::string::npos) return out;  // empty, or killed while writing the header
  const std::string header = text.substr(0, header_end);
  if (header != layout.Header()) {
    throw InputError(path + ":1: columns differ from this campaign's (" + layout.Header() +
                     "); it belongs to another campaign: use another --out folder or delete the file");
  }
  out.exists = true;
  out.valid_bytes = header_end + 1;
  std::size_t pos = header_end + 1;
  int line_no = 1;
  while (pos < text.size()) {
    const std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) {  // incomplete last line: the process was killed while writing it
      out.truncated_tail = true;
      break;
    }
    ++line_no;
    const std::string where = path + ":" + std::to_string(line_no);
    HistoryRow row = ParseHistoryRow(text.substr(pos, end - pos), layout, where);
    if (row.evaluation != static_cast<long>(out.rows.size())) {
      throw InputError(where + ": evaluation " + std::to_string(row.evaluation) +
                       " out of sequence (expected " + std::to_string(out.rows.size()) +
                       "; the file is damaged)");
    }
    out.rows.push_back(std::move(row));
    out.valid_bytes = end + 1;
    pos = end + 1;
  }
  return out;
}

HistoryAppender::HistoryAppender(const std::string& path, const HistoryLayout& layout, std::size_t keep_bytes)
    : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT, 0644);
  if (fd_ < 0) throw InputError(path + ": cannot open for writing: " + std::strerror(errno));
  if (::ftruncate(fd_, static_cast<off_t>(keep_bytes)) != 0 ||
      ::lseek(fd_, static_cast<off_t>(keep_bytes), SEEK_SET) < 0) {
    throw InputError(path + ": cannot truncate to its last complete row: " + std::strerror(errno));
  }
  if (keep_bytes == 0) Append(layout.Header() + "\n");
}

HistoryAppender::~HistoryAppender() {
  if (fd_ >= 0) ::close(fd_);
}

void HistoryAppender::WriteAll(const std::string& text) {
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw InputError(path_ + ": write failed: " + std::strerror(errno));
    }
    done += static_cast<std::size_t>(n);
  }
}

void HistoryAppender::Append(const std::string& line) {
  WriteAll(line);
  if (::fsync(fd_) != 0) throw InputError(path_ + ": fsync failed: " + std::strerror(errno));
}

}  // namespace hullopt::io
