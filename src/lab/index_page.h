#pragma once
// DIR/index.html: one page gathering every experiment whose summary (NAME.md) is in DIR, in
// the order of experimentNames(): the summary, its charts (NAME*.png, shown from the files
// beside the page, so the folder can be moved or copied whole) and links to its CSV files
// and gnuplot scripts. Written again after each experiment, so experiments run one after
// another into the same folder all appear. Opens from the disk; fetches nothing else.

#include <string>

namespace prt {

// The Markdown the summaries use, as HTML: "#"/"##" headings, paragraphs, "- " lists, pipe
// tables, **bold** and `code`. Everything else is text (escaped).
std::string markdownToHtml(const std::string& markdown);

// Returns the page's path.
std::string writeExperimentIndex(const std::string& outDir);

}  // namespace prt
