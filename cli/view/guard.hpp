// Who may talk to kerf view's server (docs/spec.md §13, docs/editors.md
// "Security"): it listens on a loopback address only, and answers only
// requests that name it as their host and come from its own page, so that
// neither another machine nor a web page in the same browser (a foreign
// origin, or a foreign name resolved to 127.0.0.1: DNS rebinding) can read
// a render or move the camera.
#pragma once
#include <string>

namespace kerf::view {

// An IPv4 address in 127.0.0.0/8 or the IPv6 ::1, in numeric form.
bool is_loopback_address(const std::string& address);

// The Host header names this server: `bound` (the listening address) or
// `localhost`, with its port ("[::1]:PORT" for IPv6).
bool host_allowed(const std::string& host_header, const std::string& bound, int port);

// An Origin header, when a browser sent one, is this server's own
// ("http://" + an allowed host); "" (no header) is allowed.
bool origin_allowed(const std::string& origin_header, const std::string& bound, int port);

// Sec-Fetch-Site, when sent, says the request comes from the server's own
// page or from the user typing its address ("same-origin", "none"): an
// <img> on a foreign page sends "cross-site" and no Origin.
bool fetch_site_allowed(const std::string& sec_fetch_site);

}  // namespace kerf::view
