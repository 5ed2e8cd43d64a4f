// history.csv / samples.csv: rows read back bit-identical (%.17g), an incomplete last line from a kill is
// detected and dropped, a log of another campaign is refused, appending continues after the last good row.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "io/formats/history_csv.h"
#include "io/formats/input_error.h"

using namespace hullopt;

namespace {
io::HistoryLayout Layout() { return io::HistoryLayout{{"L_over_B", "Cp"}, {"msi_sea1_pct"}, {"L_m"}}; }
opt::EvaluationRecord Rec(double a, double b, bool produced) {
  opt::EvaluationRecord r;
  r.x = {a, b};
  r.run = 1;
  r.step = 7;
  r.wall_time_s = 0.125;
  r.result.produced = produced;
  if (produced) {
    r.result.objective = a / 3.0;
    r.result.sea_values = {b / 7.0};
    r.feasible = true;
  } else {
    r.result.error = "Cm = 1.2 > 1, cannot build";
  }
  return r;
}
std::string TempPath(const std::string& name) { return std::string(HULLOPT_BINARY_DIR) + "/" + name; }
}  // namespace

TEST_CASE("header carries the contract columns first", "[history]") {
  CHECK(Layout().Header() ==
        "evaluation,L_over_B,Cp,objective,feasible,msi_sea1_pct,L_m,wall_time_s,run,step,message");
}

TEST_CASE("rows read back bit for bit", "[history]") {
  const auto layout = Layout();
  const auto a = Rec(1.0 / 3.0, std::nextafter(0.7, 1.0), true);
  const auto b = Rec(0.1, 0.2, false);
  const std::string text = layout.Header() + "\n" + io::FormatHistoryRow(0, a, {std::sqrt(2.0)}, layout) +
                           io::FormatHistoryRow(1, b, {}, layout);
  const auto f = io::ParseHistory(text, "h.csv", layout);
  REQUIRE(f.rows.size() == 2);
  CHECK_FALSE(f.truncated_tail);
  CHECK(f.valid_bytes == text.size());
  const auto& r = f.rows[0].record;
  CHECK(r.x == a.x);
  CHECK(r.result.objective == a.result.objective);
  CHECK(r.result.sea_values == a.result.sea_values);
  CHECK(f.rows[0].reported[0] == std::sqrt(2.0));
  CHECK(r.run == 1);
  CHECK(r.step == 7);
  CHECK(r.feasible);
  const auto& q = f.rows[1].record;
  CHECK_FALSE(q.result.produced);
  CHECK(q.result.error == "Cm = 1.2 > 1; cannot build");  // comma made safe for CSV
  CHECK_FALSE(q.feasible);
}

TEST_CASE("a produced design's warning is kept in message and read back as produced", "[history]") {
  // Resuming must not mistake a warned design for a refused one: its numbers stay, its warning comes back.
  const auto layout = Layout();
  auto a = Rec(0.25, 0.5, true);
  a.result.warning = "near-singular strip section at x = 1.2 m, condition 1080 > 200";
  const std::string row = io::FormatHistoryRow(0, a, {1.5}, layout);
  CHECK(row.find(",warning: near-singular strip section at x = 1.2 m; condition 1080 > 200\n") != std::string::npos);
  const auto f = io::ParseHistory(layout.Header() + "\n" + row, "h.csv", layout);
  REQUIRE(f.rows.size() == 1);
  const auto& r = f.rows[0].record;
  CHECK(r.result.produced);
  CHECK(r.result.error.empty());
  CHECK(r.result.warning == "near-singular strip section at x = 1.2 m; condition 1080 > 200");
  CHECK(r.result.objective == a.result.objective);
  CHECK(f.rows[0].reported[0] == 1.5);
}

TEST_CASE("an incomplete last line is detected and dropped; appending resumes after the last row",
          "[history][resume]") {
  const auto layout = Layout();
  const std::string path = TempPath("test_history_truncated.csv");
  std::remove(path.c_str());
  {
    io::HistoryAppender w(path, layout, 0);
    w.Append(io::FormatHistoryRow(0, Rec(1, 2, true), {3}, layout));
    w.Append(io::FormatHistoryRow(1, Rec(4, 5, true), {6}, layout));
  }
  {  // a kill in the middle of the third row
    std::ofstream out(path, std::ios::app);
    out << "2,0.5,0.2";
  }
  auto f = io::ReadHistory(path, layout);
  REQUIRE(f.rows.size() == 2);
  CHECK(f.truncated_tail);
  {
    io::HistoryAppender w(path, layout, f.valid_bytes);
    w.Append(io::FormatHistoryRow(2, Rec(7, 8, true), {9}, layout));
  }
  f = io::ReadHistory(path, layout);
  REQUIRE(f.rows.size() == 3);
  CHECK_FALSE(f.truncated_tail);
  CHECK(f.rows[2].record.x == std::vector<double>{7, 8});
  std::remove(path.c_str());
}

TEST_CASE("a log of another campaign or a damaged log is refused", "[history][bad-input]") {
  const auto layout = Layout();
  auto other = layout;
  other.variables = {"L_over_B", "Cb"};
  const std::string text = layout.Header() + "\n" + io::FormatHistoryRow(0, Rec(1, 2, true), {3}, layout);
  CHECK_THROWS_WITH(io::ParseHistory(text, "h.csv", other), Catch::Contains("h.csv:1: columns differ"));
  CHECK_THROWS_WITH(io::ParseHistory(layout.Header() + "\n0,1,2\n", "h.csv", layout),
                    Catch::Contains("h.csv:2: expected 11 columns"));
  const std::string skipped = layout.Header() + "\n" + io::FormatHistoryRow(1, Rec(1, 2, true), {3}, layout);
  CHECK_THROWS_WITH(io::ParseHistory(skipped, "h.csv", layout), Catch::Contains("out of sequence"));
  CHECK_FALSE(io::ParseHistory("", "h.csv", layout).exists);
  CHECK_FALSE(io::ParseHistory("evaluation,L_ov", "h.csv", layout).exists);  // killed in the header
}

TEST_CASE("a reader without the campaign takes the layout from the header", "[history]") {
  const auto layout = Layout();
  const auto a = Rec(0.25, 0.5, true);
  const std::string path = TempPath("history_layout_test.csv");
  {
    std::ofstream f(path);
    f << layout.Header() << "\n" << io::FormatHistoryRow(0, a, {42.0}, layout);
  }
  const io::HistoryLayout read = io::ReadHistoryLayout(path);
  CHECK(read.variables == layout.variables);
  CHECK(read.seas.empty());  // the header does not tell seas from quantities: both come back as quantities
  CHECK(read.quantities == std::vector<std::string>{"msi_sea1_pct", "L_m"});
  const auto rows = io::ReadHistory(path, read).rows;
  REQUIRE(rows.size() == 1);
  CHECK(rows[0].record.x == a.x);
  CHECK(rows[0].reported == std::vector<double>{a.result.sea_values[0], 42.0});

  {
    std::ofstream f(path);
    f << "evaluation,L_over_B,objective,wall_time_s,run,step,message\n";  // no `feasible`
  }
  CHECK_THROWS_WITH(io::ReadHistoryLayout(path), Catch::Contains("history_layout_test.csv:1: not a history file"));
  std::remove(path.c_str());
  CHECK_THROWS_WITH(io::ReadHistoryLayout(path), Catch::Contains("missing or empty"));
}
