// The viewer's page (page.html), compiled in by CMake (page.cpp.in).
#pragma once

namespace kerf::view {

const char* page_html();

}  // namespace kerf::view
