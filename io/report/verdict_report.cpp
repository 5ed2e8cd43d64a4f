#include "io/report/verdict_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace hullopt::io {
namespace {

std::string VerdictNumber(double v, int digits = 3) { return FormatNumber(v, digits); }

std::string Value(const eval::SeakeepingCriterion& c, double v) {
  if (c.quantity == eval::CriterionQuantity::kSlammingProbability ||
      c.quantity == eval::CriterionQuantity::kDeckWetnessProbability)
    return v < 1e-4 ? "< 1e-4" : VerdictNumber(v, 2);
  return VerdictNumber(v, 3);
}

std::string Margin(double m) {
  if (!std::isfinite(m)) return "";
  char b[32];
  std::snprintf(b, sizeof b, "%+.0f%%", 100.0 * m);
  return b;
}

std::string EventsText(double per_hour) {
  char b[32];
  std::snprintf(b, sizeof b, per_hour >= 10.0 ? "%.0f/h" : "%.2g/h", per_hour);
  return b;
}

std::string LimitText(const eval::SeakeepingCriterion& c) {
  const std::string u = eval::CriterionQuantityUnit(c.quantity);
  return VerdictNumber(c.limit, 3) + (u == "-" ? "" : " " + u);
}

}  // namespace

double CriterionLimitingHs(const eval::SeakeepingVerdict& v, std::size_t c) {
  std::vector<const eval::SeaVerdict*> by_hs;
  for (const auto& s : v.seas) by_hs.push_back(&s);
  std::stable_sort(by_hs.begin(), by_hs.end(), [](auto* a, auto* b) { return a->Hs_m < b->Hs_m; });
  double hs = 0.0;
  for (const auto* s : by_hs) {
    if (c >= s->checks.size() || !s->checks[c].judged) return std::numeric_limits<double>::quiet_NaN();
    if (!s->checks[c].met) break;
    hs = s->Hs_m;
  }
  return hs;
}

std::string VerdictLine(const std::string& name, const eval::CriteriaSet& set, const eval::SeakeepingVerdict& v) {
  double hs_max = 0.0;
  for (const auto& s : v.seas) hs_max = std::max(hs_max, s.Hs_m);
  std::string fails;
  for (std::size_t c = 0; c < set.criteria.size(); ++c) {
    const double hs = CriterionLimitingHs(v, c);
    if (std::isfinite(hs) && hs < hs_max)
      fails += (fails.empty() ? "" : ", ") + set.criteria[c].name + (hs > 0 ? " above Hs " + VerdictNumber(hs) + " m" : " from the lowest sea");
  }
  std::string line = name + ": ";
  if (fails.empty())
    line += "meets every criterion of " + set.title + " in every sea (up to Hs " + VerdictNumber(hs_max) + " m)";
  else
    line += (v.limiting_Hs_m > 0 ? "meets every criterion of " + set.title + " up to Hs " + VerdictNumber(v.limiting_Hs_m) + " m"
                                 : "fails a criterion of " + set.title + " in the lowest sea") +
            "; fails " + fails;
  return line;
}

void AddVerdictSection(HtmlReport& r, const eval::CriteriaSet& set, const std::vector<JudgedDesign>& designs,
                       bool matrices) {
  r.Heading("Seakeeping verdict: " + set.title);
  r.Paragraph("Criteria from " + set.file +
              " (head seas at the design speed; probabilities per wave encounter; margin = (limit - value) / "
              "limit, positive = holds with that share to spare).");
  std::vector<std::vector<std::string>> rows;
  for (const auto& c : set.criteria)
    rows.push_back({c.name, eval::CriterionQuantityName(c.quantity), c.location, LimitText(c), c.source});
  std::vector<std::vector<std::string>> text_cells(rows.size(), {"", "", "", "nw", "txt"});
  r.ClassedTable({"criterion", "quantity", "location", "limit", "source"}, rows, text_cells);
  // A line per design for one or two designs; for more, the summary table says it at a glance.
  if (designs.size() <= 2)
    for (const auto& d : designs) r.Paragraph(VerdictLine(d.name, set, *d.verdict));

  // Summary: the Hs up to which each criterion holds, per design.
  std::vector<std::string> header = {"design", "all criteria"};
  for (const auto& c : set.criteria) header.push_back(c.name);
  std::vector<std::vector<std::string>> summary;
  std::vector<std::vector<std::string>> classes;
  for (const auto& d : designs) {
    double hs_max = 0.0;
    for (const auto& s : d.verdict->seas) hs_max = std::max(hs_max, s.Hs_m);
    auto cell = [&](double hs, std::vector<std::string>* row, std::vector<std::string>* cls) {
      if (!std::isfinite(hs)) {
        row->push_back("not judged");
        cls->push_back("nj");
      } else if (hs >= hs_max) {
        row->push_back("all seas");
        cls->push_back("ok");
      } else {
        row->push_back(hs > 0 ? "Hs " + VerdictNumber(hs) + " m" : "none");
        cls->push_back("fail");
      }
    };
    std::vector<std::string> row = {d.name}, cls = {""};
    cell(d.verdict->limiting_Hs_m, &row, &cls);
    for (std::size_t c = 0; c < set.criteria.size(); ++c) cell(CriterionLimitingHs(*d.verdict, c), &row, &cls);
    summary.push_back(row);
    classes.push_back(cls);
  }
  r.Subheading("Highest Hs up to which each criterion holds");
  r.ClassedTable(header, summary, classes);
  if (!matrices) return;
  for (const auto& d : designs) {
    r.Subheading(d.name + ": value and margin per sea");
    std::vector<std::string> h = {"criterion", "limit"};
    for (const auto& s : d.verdict->seas) h.push_back("Hs " + VerdictNumber(s.Hs_m) + " m, Tz " + VerdictNumber(s.Tz_s) + " s");
    std::vector<std::vector<std::string>> m, mc;
    for (std::size_t c = 0; c < set.criteria.size(); ++c) {
      const auto& cr = set.criteria[c];
      std::vector<std::string> row = {cr.name + " (" + cr.location + ")", LimitText(cr)}, cls = {"", "nw"};
      for (const auto& s : d.verdict->seas) {
        const auto& k = s.checks[c];
        if (!k.judged) {
          row.push_back("not judged");
          cls.push_back("nj");
          continue;
        }
        std::string text = Value(cr, k.value) + " (" + Margin(k.margin) + ")";
        // Events per hour once they matter (at least one a day).
        if (k.events_per_hour >= 1.0 / 24.0) text += ", " + EventsText(k.events_per_hour);
        row.push_back(text);
        cls.push_back(k.met ? "ok" : "fail");
      }
      m.push_back(row);
      mc.push_back(cls);
    }
    r.ClassedTable(h, m, mc);
    // The station geometry behind the probabilities, once (the same in every sea).
    std::vector<std::string> notes;
    if (!d.verdict->seas.empty())
      for (std::size_t c = 0; c < set.criteria.size(); ++c) {
        const auto& k = d.verdict->seas.back().checks[c];
        if (!k.note.empty())
          notes.push_back(set.criteria[c].name + " (Hs " + VerdictNumber(d.verdict->seas.back().Hs_m) + " m): " + k.note);
      }
    if (!notes.empty()) r.List(notes, "");
  }
}

}  // namespace hullopt::io
