#include "report/html_text.h"

#include <gtest/gtest.h>

namespace prt {
namespace {

TEST(HtmlText, EscapesMarkup) {
  EXPECT_EQ(escapeHtml("<a href=\"x\">&'</a>"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;&lt;/a&gt;");
}

TEST(HtmlText, Base64MatchesRfc4648) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

TEST(HtmlText, ScriptJsonCannotCloseTheElement) {
  const nlohmann::json j = {{"scene", "</script><script>alert(1)</script>"}};
  const std::string text = jsonForScript(j);
  EXPECT_EQ(text.find('<'), std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(text), j);  // and it still parses to the same value
}

TEST(HtmlText, ScriptJsonSurvivesInvalidUtf8) {
  const nlohmann::json j = {{"scene", std::string("bad\xff.scene")}};
  EXPECT_NO_THROW(nlohmann::json::parse(jsonForScript(j)));
}

TEST(HtmlText, FormatsNumbersForPeople) {
  EXPECT_EQ(formatCount(0), "0");
  EXPECT_EQ(formatCount(1234567), "1,234,567");
  EXPECT_EQ(formatCount(999), "999");
  EXPECT_EQ(formatSeconds(12.345), "12.3 s");
  EXPECT_EQ(formatSeconds(0.0456), "45.6 ms");
  EXPECT_EQ(formatSeconds(7.8e-5), "78.0 µs");
  EXPECT_EQ(formatPercent(0.9345), "93.5 %");
  EXPECT_EQ(formatBytes(512), "512 B");
  EXPECT_EQ(formatBytes(1234567), "1.23 MB");
  EXPECT_EQ(formatNumber(3.04999), "3.05");
  EXPECT_EQ(formatNumber(123.4), "123");
  EXPECT_EQ(formatNumber(0.5), "0.500");
}

}  // namespace
}  // namespace prt
