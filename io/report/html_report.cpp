#include "io/report/html_report.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"

namespace hullopt::io {
namespace {

// Plain print styles: readable on screen and on paper, no web fonts.
const char* const kStyle =
    "body{font-family:sans-serif;max-width:1250px;margin:1em auto;padding:0 1em;color:#222}"
    "h1{font-size:1.5em;border-bottom:2px solid #345}h2{font-size:1.2em;margin-top:1.6em;color:#234}"
    "h3{font-size:1.05em}table{border-collapse:collapse;margin:0.5em 0}"
    "th,td{border:1px solid #bbb;padding:2px 8px;text-align:right;font-size:0.9em}"
    "th{background:#eef}td:first-child,th:first-child{text-align:left}"
    "pre{background:#f6f6f6;padding:0.5em;font-size:0.8em;overflow-x:auto}"
    ".fig svg{max-width:100%;height:auto}.row{display:flex;gap:1em;flex-wrap:wrap}"
    ".row>div{flex:1 1 45%;min-width:300px}.row svg{max-width:100%;height:auto}"
    "td.ok{background:#e3f4e1}td.fail{background:#fbe0dd;font-weight:bold}td.nj{color:#888}td.txt{text-align:left;white-space:normal}td.ok,td.fail,td.nj,td.nw{white-space:nowrap}";

void ReplaceAll(std::string* s, const std::string& from, const std::string& to) {
  for (auto p = s->find(from); p != std::string::npos; p = s->find(from, p + to.size())) s->replace(p, from.size(), to);
}

// Each inlined figure gets its own clip-path ids (the plot writers number theirs from 0 in every file).
std::string StripProlog(const std::string& svg, int figure) {
  // Inline SVG in HTML needs no namespace declaration; dropping it leaves the page without any URL.
  const auto at = svg.find("<svg");
  std::string s = at == std::string::npos ? svg : svg.substr(at);
  const std::string ns = " xmlns=\"http://www.w3.org/2000/svg\"";
  ReplaceAll(&s, ns, "");
  const std::string prefix = "f" + std::to_string(figure) + "_";
  ReplaceAll(&s, "id=\"clip", "id=\"" + prefix + "clip");
  ReplaceAll(&s, "url(#clip", "url(#" + prefix + "clip");
  return s;
}

}  // namespace

std::string FormatNumber(double v, int digits) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

std::string HtmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {}

void HtmlReport::Heading(const std::string& t) { body_ += "<h2>" + HtmlEscape(t) + "</h2>\n"; }
void HtmlReport::Subheading(const std::string& t) { body_ += "<h3>" + HtmlEscape(t) + "</h3>\n"; }
void HtmlReport::Paragraph(const std::string& t) { body_ += "<p>" + HtmlEscape(t) + "</p>\n"; }

void HtmlReport::Table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  body_ += "<table><tr>";
  for (const auto& h : header) body_ += "<th>" + HtmlEscape(h) + "</th>";
  body_ += "</tr>\n";
  for (const auto& r : rows) {
    body_ += "<tr>";
    for (const auto& c : r) body_ += "<td>" + HtmlEscape(c) + "</td>";
    body_ += "</tr>\n";
  }
  body_ += "</table>\n";
}

void HtmlReport::ClassedTable(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                              const std::vector<std::vector<std::string>>& classes) {
  body_ += "<table><tr>";
  for (const auto& h : header) body_ += "<th>" + HtmlEscape(h) + "</th>";
  body_ += "</tr>\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    body_ += "<tr>";
    for (std::size_t j = 0; j < rows[i].size(); ++j) {
      const std::string cls = i < classes.size() && j < classes[i].size() ? classes[i][j] : "";
      body_ += (cls.empty() ? "<td>" : "<td class=\"" + HtmlEscape(cls) + "\">") + HtmlEscape(rows[i][j]) + "</td>";
    }
    body_ += "</tr>\n";
  }
  body_ += "</table>\n";
}

void HtmlReport::Svg(const std::string& svg) { body_ += "<div class=\"fig\">" + StripProlog(svg, figures_++) + "</div>\n"; }

void HtmlReport::SvgRow(const std::vector<std::string>& svgs, const std::vector<std::string>& captions) {
  body_ += "<div class=\"row\">";
  for (std::size_t i = 0; i < svgs.size(); ++i)
    body_ += "<div><h3>" + HtmlEscape(i < captions.size() ? captions[i] : "") + "</h3>" + StripProlog(svgs[i], figures_++) +
             "</div>";
  body_ += "</div>\n";
}

void HtmlReport::Preformatted(const std::string& t) { body_ += "<pre>" + HtmlEscape(t) + "</pre>\n"; }

void HtmlReport::List(const std::vector<std::string>& items, const std::string& empty) {
  if (items.empty()) {
    Paragraph(empty);
    return;
  }
  body_ += "<ul>";
  for (const auto& i : items) body_ += "<li>" + HtmlEscape(i) + "</li>";
  body_ += "</ul>\n";
}

std::string HtmlReport::Html() const {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + HtmlEscape(title_) +
         "</title><style>" + kStyle + "</style></head><body>\n<h1>" + HtmlEscape(title_) + "</h1>\n" + body_ +
         "</body></html>\n";
}

std::string ReadSvgFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the figure for report.html");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void WriteHtmlReport(const std::string& path, const HtmlReport& report) {
  try {
    WriteFileAtomically(path, report.Html());
  } catch (const std::exception& e) {
    throw InputError(path + ": cannot write report.html: " + e.what());
  }
}

}  // namespace hullopt::io
