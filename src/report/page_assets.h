#pragma once
// The run page's style sheet and script, kept as real files beside this header (page.css,
// page.js) and compiled in as text, so every page carries them inline.

#include <string_view>

namespace prt {

extern const std::string_view kPageStyle;
extern const std::string_view kPageScript;

}  // namespace prt
