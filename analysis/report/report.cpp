#include "report/report.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "formats/atomic_file.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

std::string md_cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') {
      out += "\\|";
    } else if (c == '\n') {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

std::string read_binary(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read '" + path.string() + "'");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

// Writes `text` as the file NAME of `dir`, every write checked (formats/atomic_file.h: the
// report's directory is renamed into place as a whole).
void write_text(const std::string& dir, const std::string& name, const std::string& text) {
  write_file_inside((fs::path(dir) / name).string(), text, name);
}

void markdown_block(std::ostream& out, const ReportBlock& block) {
  if (const auto* p = std::get_if<ReportParagraph>(&block)) {
    out << p->text << "\n\n";
  } else if (const auto* t = std::get_if<ReportTable>(&block)) {
    if (!t->caption.empty()) out << "**" << t->caption << "**\n\n";
    out << '|';
    for (const std::string& h : t->header) out << ' ' << md_cell(h) << " |";
    out << "\n|";
    for (size_t i = 0; i < t->header.size(); ++i) out << "---|";
    out << '\n';
    for (const auto& row : t->rows) {
      out << '|';
      for (const std::string& c : row) out << ' ' << md_cell(c) << " |";
      out << '\n';
    }
    out << '\n';
  } else if (const auto* f = std::get_if<ReportFigure>(&block)) {
    out << "![" << md_cell(f->caption) << "](" << f->png << ")\n\n*" << f->caption << "* Data: ["
        << f->csv << "](" << f->csv << ").\n\n";
  } else if (const auto* c = std::get_if<ReportCode>(&block)) {
    out << "```\n"
        << c->text << (c->text.empty() || c->text.back() != '\n' ? "\n" : "") << "```\n\n";
  }
}

void html_block(std::ostream& out, const ReportBlock& block, const std::string& dir) {
  if (const auto* p = std::get_if<ReportParagraph>(&block)) {
    out << "<p>" << html_escape(p->text) << "</p>\n";
  } else if (const auto* t = std::get_if<ReportTable>(&block)) {
    out << "<table>\n";
    if (!t->caption.empty()) out << "<caption>" << html_escape(t->caption) << "</caption>\n";
    out << "<thead><tr>";
    for (const std::string& h : t->header) out << "<th>" << html_escape(h) << "</th>";
    out << "</tr></thead>\n<tbody>\n";
    for (const auto& row : t->rows) {
      out << "<tr>";
      for (const std::string& c : row) out << "<td>" << html_escape(c) << "</td>";
      out << "</tr>\n";
    }
    out << "</tbody>\n</table>\n";
  } else if (const auto* f = std::get_if<ReportFigure>(&block)) {
    const std::string png = read_binary(fs::path(dir) / f->png);
    out << "<figure>\n<img alt=\"" << html_escape(f->caption) << "\" src=\"data:image/png;base64,"
        << base64_encode(png) << "\">\n<figcaption>" << html_escape(f->caption) << " Data: <code>"
        << html_escape(f->csv) << "</code></figcaption>\n</figure>\n";
  } else if (const auto* c = std::get_if<ReportCode>(&block)) {
    out << "<pre>" << html_escape(c->text) << "</pre>\n";
  }
}

constexpr const char* kStyle =
    "body{font-family:sans-serif;max-width:1000px;margin:2em auto;padding:0 1em;"
    "color:#222;line-height:1.45}"
    "table{border-collapse:collapse;margin:1em 0;font-size:0.9em}"
    "caption{font-weight:bold;text-align:left;padding:0.3em 0}"
    "th,td{border:1px solid #bbb;padding:0.25em 0.5em;text-align:left;vertical-align:top}"
    "th{background:#eee}"
    "figure{margin:1.5em 0}img{max-width:100%;border:1px solid #ddd}"
    "figcaption{font-size:0.9em;color:#555}"
    "pre{background:#f6f6f6;padding:0.6em;overflow-x:auto}";

}  // namespace

std::string html_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string base64_encode(const std::string& bytes) {
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                       (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += alphabet[(v >> 6) & 63];
    out += alphabet[v & 63];
  }
  const size_t rest = bytes.size() - i;
  if (rest > 0) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += alphabet[(v >> 18) & 63];
    out += alphabet[(v >> 12) & 63];
    out += rest == 2 ? alphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string render_markdown(const Report& report) {
  std::ostringstream out;
  out << "# " << report.title << "\n\n";
  for (const ReportSection& s : report.sections) {
    out << "## " << s.title << "\n\n";
    for (const ReportBlock& b : s.blocks) markdown_block(out, b);
  }
  return out.str();
}

std::string render_html(const Report& report, const std::string& dir) {
  std::ostringstream out;
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>"
      << html_escape(report.title) << "</title>\n<style>" << kStyle << "</style>\n</head>\n<body>\n"
      << "<h1>" << html_escape(report.title) << "</h1>\n<nav><ul>\n";
  for (const ReportSection& s : report.sections) {
    out << "<li><a href=\"#" << html_escape(s.id) << "\">" << html_escape(s.title) << "</a></li>\n";
  }
  out << "</ul></nav>\n";
  for (const ReportSection& s : report.sections) {
    out << "<section id=\"" << html_escape(s.id) << "\">\n<h2>" << html_escape(s.title)
        << "</h2>\n";
    for (const ReportBlock& b : s.blocks) html_block(out, b, dir);
    out << "</section>\n";
  }
  out << "</body>\n</html>\n";
  return out.str();
}

void write_report(const Report& report, const std::string& dir) {
  write_text(dir, "report.md", render_markdown(report));
  write_text(dir, "report.html", render_html(report, dir));
}

}  // namespace oflab
