// The report site's two static files, written into SITE/assets/: the style sheet and the script that
// sorts and filters the index and drives a material page's compare view. Plain CSS and JavaScript with no
// library and nothing fetched, so the site works from file:// and offline; the pages work without the
// script too, only without sorting, filtering and comparing. They are the files renderer/report/assets/
// style.css and report.js, embedded at build time (cmake/embed_files.cmake): the executable carries its site.
#pragma once

#include <string_view>

namespace glossy::report {

std::string_view siteStyleSheet();
std::string_view siteScript();

}  // namespace glossy::report
