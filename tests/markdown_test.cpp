// The study summary's markdown subset (renderer/report/markdown.h): each block and inline form it knows,
// and everything else shown as text, escaped.
#include "renderer/report/markdown.h"

#include <gtest/gtest.h>

namespace glossy::report {

TEST(Markdown, RendersTheSubsetItKnows) {
  EXPECT_EQ(markdownToHtml("# Study summary\n\nA *small* and **bold** `x < y` claim.\n"),
            "<h3>Study summary</h3>\n<p>A <em>small</em> and <strong>bold</strong> <code>x &lt; y</code> claim.</p>\n");
  EXPECT_EQ(markdownToHtml("- one\n- two\n\n1. first\n2. second\n"),
            "<ul>\n<li>one</li>\n<li>two</li>\n</ul>\n<ol>\n<li>first</li>\n<li>second</li>\n</ol>\n");
  EXPECT_EQ(markdownToHtml("```\nmodel  r*\nCT <E2>\n```\n"), "<pre class=\"study-summary\"><code>model  r*\nCT &lt;E2&gt;\n</code></pre>\n");
  EXPECT_EQ(markdownToHtml("| model | r* |\n|---|--:|\n| CT E2 | 0.1 |\n| GGX |\n"),
            "<div class=\"table-wrap\"><table class=\"summary-table\">\n<thead><tr><th scope=\"col\">model</th><th scope=\"col\">r*</th></tr></thead>\n"
            "<tbody>\n<tr><td>CT E2</td><td>0.1</td></tr>\n<tr><td>GGX</td><td></td></tr>\n</tbody>\n</table></div>\n");
  EXPECT_EQ(markdownToHtml("2 * 3 * 4 and snake_case_name"), "<p>2 * 3 * 4 and snake_case_name</p>\n");
  // Backslash escapes, as the summary writes r* in its captions and methods: never emphasis, no backslash shown.
  EXPECT_EQ(markdownToHtml("r\\*, the error; r\\* of X\\_Y and \\\\ `r\\*`"),
            "<p>r*, the error; r* of X_Y and \\ <code>r\\*</code></p>\n");
}

TEST(Markdown, EverythingElseIsEscapedText) {
  const std::string html = markdownToHtml("<script>alert(1)</script>\n\n[link](javascript:x) ![i](x.png) <b onclick=\"y\">&amp;\n");
  EXPECT_EQ(html.find("<script"), std::string::npos) << html;
  EXPECT_EQ(html.find("<b "), std::string::npos) << html;
  EXPECT_EQ(html.find("<a"), std::string::npos) << html;
  EXPECT_EQ(html.find("<img"), std::string::npos) << html;
  EXPECT_NE(html.find("&lt;script&gt;"), std::string::npos) << html;
  EXPECT_NE(html.find("&amp;amp;"), std::string::npos) << html;
  EXPECT_EQ(markdownToHtml("*<i>*"), "<p><em>&lt;i&gt;</em></p>\n");
  EXPECT_EQ(markdownToHtml("`unclosed <code"), "<p>`unclosed &lt;code</p>\n");
}

}  // namespace glossy::report
