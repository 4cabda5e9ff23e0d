// The experiments report as a document: sections of paragraphs, tables and figures, and
// its two renderings, Markdown (report.md: figures link the PNG and CSV files next to it)
// and HTML (report.html: self-contained, every PNG embedded as a base64 data URI).
#pragma once

#include <string>
#include <variant>
#include <vector>

namespace oflab {

// Plain text; rendered escaped (no markup is interpreted).
struct ReportParagraph {
  std::string text;
};

struct ReportTable {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // each as long as header
};

// A chart written by the experiment: paths relative to the report directory.
struct ReportFigure {
  std::string png;
  std::string csv;
  std::string caption;
};

// Preformatted text (a command line, a list of machine facts).
struct ReportCode {
  std::string text;
};

using ReportBlock = std::variant<ReportParagraph, ReportTable, ReportFigure, ReportCode>;

struct ReportSection {
  std::string id;  // anchor, e.g. "experiment-1"
  std::string title;
  std::vector<ReportBlock> blocks;

  void paragraph(std::string text) { blocks.push_back(ReportParagraph{std::move(text)}); }
  void table(ReportTable t) { blocks.push_back(std::move(t)); }
  void figure(ReportFigure f) { blocks.push_back(std::move(f)); }
  void code(std::string text) { blocks.push_back(ReportCode{std::move(text)}); }
};

struct Report {
  std::string title;
  std::vector<ReportSection> sections;
};

// Markdown (GitHub flavour): "#" title, "##" sections, pipe tables, images as
// ![caption](png) followed by a link to the CSV.
std::string render_markdown(const Report& report);

// A complete HTML5 page with an inline style sheet and a table of contents. Figures are
// read from `dir`/png and embedded as data:image/png;base64 URIs. Throws
// std::runtime_error naming the file when a figure's PNG cannot be read.
std::string render_html(const Report& report, const std::string& dir);

// RFC 4648 base64 of `bytes` (with '=' padding).
std::string base64_encode(const std::string& bytes);

// `text` safe inside HTML text and attribute values: & < > " as character references.
std::string html_escape(const std::string& text);

// Writes `dir`/report.md and `dir`/report.html. Throws std::runtime_error naming the file
// on failure.
void write_report(const Report& report, const std::string& dir);

}  // namespace oflab
