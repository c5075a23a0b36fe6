#include "lab/index_page.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "image/atomic_file.h"
#include "lab/experiment.h"
#include "report/html_text.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

// **bold** and `code` inside a line; the rest escaped.
std::string inlineMarkdown(const std::string& line) {
  std::string out;
  bool bold = false;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '`') {
      const size_t close = line.find('`', i + 1);
      if (close != std::string::npos) {
        out += "<code>" + escapeHtml(line.substr(i + 1, close - i - 1)) + "</code>";
        i = close;
        continue;
      }
    }
    if (line.compare(i, 2, "**") == 0) {
      out += bold ? "</b>" : "<b>";
      bold = !bold;
      ++i;
      continue;
    }
    out += escapeHtml(std::string_view(&line[i], 1));
  }
  if (bold) out += "</b>";
  return out;
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  for (size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '|') {
      out.push_back(cell);
      cell.clear();
    } else {
      cell += line[i];
    }
  }
  for (std::string& c : out) {
    c.erase(0, c.find_first_not_of(' '));
    c.erase(c.find_last_not_of(' ') + 1);
  }
  return out;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string markdownToHtml(const std::string& markdown) {
  std::istringstream in(markdown);
  std::string line, out, paragraph;
  bool inList = false, inTable = false, header = false;
  auto flush = [&] {
    if (!paragraph.empty()) out += "<p>" + paragraph + "</p>\n";
    paragraph.clear();
    if (inList) out += "</ul>\n";
    if (inTable) out += "</tbody></table>\n";
    inList = inTable = false;
  };
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) {
      flush();
    } else if (line.rfind("## ", 0) == 0) {
      flush();
      out += "<h4>" + inlineMarkdown(line.substr(3)) + "</h4>\n";
    } else if (line.rfind("# ", 0) == 0) {
      flush();
      out += "<h3>" + inlineMarkdown(line.substr(2)) + "</h3>\n";
    } else if (line[0] == '|') {
      const std::vector<std::string> row = cells(line);
      if (!inTable) {
        flush();
        out += "<table><thead><tr>";
        for (const std::string& c : row) out += "<th>" + inlineMarkdown(c) + "</th>";
        out += "</tr></thead><tbody>\n";
        inTable = header = true;
        continue;
      }
      if (header && line.find("---") != std::string::npos) {
        header = false;
        continue;
      }
      out += "<tr>";
      for (const std::string& c : row) out += "<td>" + inlineMarkdown(c) + "</td>";
      out += "</tr>\n";
    } else if (line.rfind("- ", 0) == 0) {
      if (!inList) {
        flush();
        out += "<ul>\n";
        inList = true;
      }
      out += "<li>" + inlineMarkdown(line.substr(2)) + "</li>\n";
    } else {
      if (inList || inTable) flush();
      if (!paragraph.empty()) paragraph += ' ';
      paragraph += inlineMarkdown(line);
    }
  }
  flush();
  return out;
}

std::string writeExperimentIndex(const std::string& outDir) {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(outDir)) {
    if (entry.is_regular_file()) files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  std::string body = "<header><h1>PRT experiments</h1><p class=\"sub\">" + escapeHtml(outDir) +
                     ": summaries and charts; the CSV files beside this page are the source "
                     "of truth.</p></header>\n<main>\n";
  std::string contents;
  for (const std::string& name : experimentNames()) {
    if (!fs::exists(fs::path(outDir) / (name + ".md"))) continue;
    std::vector<std::string> charts, data;
    for (const std::string& f : files) {
      const bool ours = f.rfind(name + "-", 0) == 0 || fs::path(f).stem() == name;
      if (!ours || f == name + ".md") continue;
      (fs::path(f).extension() == ".png" ? charts : data).push_back(f);
    }
    contents += "<a href=\"#" + escapeHtml(name) + "\">" + escapeHtml(name) + "</a> ";
    body += "<section class=\"experiment\" id=\"" + escapeHtml(name) + "\">\n" +
            markdownToHtml(readText(fs::path(outDir) / (name + ".md")));
    for (const std::string& c : charts) {
      body += "<figure><img src=\"" + escapeHtml(c) + "\" alt=\"" + escapeHtml(c) +
              "\"><figcaption>" + escapeHtml(c) + "</figcaption></figure>\n";
    }
    if (!data.empty()) {
      body += "<p class=\"files\">Files: <a href=\"" + escapeHtml(name) + ".md\">" +
              escapeHtml(name) + ".md</a>";
      for (const std::string& d : data) {
        body += ", <a href=\"" + escapeHtml(d) + "\">" + escapeHtml(d) + "</a>";
      }
      body += "</p>\n";
    }
    body += "</section>\n";
  }
  if (contents.empty())
    body += "<section><p>No experiment summaries here yet.</p></section>\n";
  else
    body.insert(body.find("<main>\n") + 7,
                "<section><b>Experiments:</b> " + contents + "</section>\n");
  body += "</main>\n<footer>Made by prt experiment.</footer>\n";
  const std::string path = (fs::path(outDir) / "index.html").string();
  writeFileAtomically(path, htmlDocument("PRT experiments", body));
  return path;
}

}  // namespace prt
