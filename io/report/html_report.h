#pragma once
// A self-contained HTML page (report.html): inline CSS, inline SVG figures, tables and text, nothing fetched
// from anywhere (no scripts, links, images or fonts by reference), so that it opens offline and archives as
// one file.
#include <string>
#include <vector>

namespace hullopt::io {

/// Text with &, <, >, " and ' replaced by their entities.
std::string HtmlEscape(const std::string& text);
/// A number for a report table: `digits` significant digits (%g).
std::string FormatNumber(double v, int digits = 4);

class HtmlReport {
 public:
  explicit HtmlReport(std::string title);
  void Heading(const std::string& text);     ///< a section heading (h2)
  void Subheading(const std::string& text);  ///< h3
  void Paragraph(const std::string& text);
  /// A table; every row should have header.size() cells.
  void Table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  /// A table whose cells carry a class each (same shape as rows; missing = none): "ok" (green), "fail" (red),
  /// "nj" (grey, not judged) mark a verdict; "txt" left-aligns a text cell, "nw" keeps one on one line.
  void ClassedTable(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                    const std::vector<std::vector<std::string>>& classes);
  /// An SVG document's text, inlined (an XML declaration or DOCTYPE before <svg is dropped).
  void Svg(const std::string& svg_text);
  /// Several SVG documents side by side, each with a caption.
  void SvgRow(const std::vector<std::string>& svg_texts, const std::vector<std::string>& captions);
  void Preformatted(const std::string& text);
  /// A bulleted list; `empty` is written instead when items is empty.
  void List(const std::vector<std::string>& items, const std::string& empty);
  /// The whole page.
  std::string Html() const;

 private:
  std::string title_;
  std::string body_;
  int figures_ = 0;
};

/// The SVG text of a file written by the plot writers; throws InputError if it cannot be read.
std::string ReadSvgFile(const std::string& path);
/// Writes the page to path (atomically); throws InputError on failure.
void WriteHtmlReport(const std::string& path, const HtmlReport& report);

}  // namespace hullopt::io
