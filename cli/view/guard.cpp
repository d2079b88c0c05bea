#include "cli/view/guard.hpp"

#include <algorithm>
#include <cctype>

#include <arpa/inet.h>

namespace kerf::view {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// "127.0.0.1" -> "127.0.0.1", "::1" -> "[::1]": an address as a Host names it.
std::string host_form(const std::string& address) {
    return address.find(':') != std::string::npos ? "[" + address + "]" : address;
}

}  // namespace

bool is_loopback_address(const std::string& address) {
    unsigned char v4[4];
    if (inet_pton(AF_INET, address.c_str(), v4) == 1) return v4[0] == 127;
    unsigned char v6[16];
    if (inet_pton(AF_INET6, address.c_str(), v6) == 1)
        return std::all_of(v6, v6 + 15, [](unsigned char b) { return b == 0; }) && v6[15] == 1;
    return false;
}

bool host_allowed(const std::string& host_header, const std::string& bound, int port) {
    const std::string h = lower(host_header), p = ":" + std::to_string(port);
    return h == host_form(lower(bound)) + p || h == "localhost" + p;
}

bool origin_allowed(const std::string& origin_header, const std::string& bound, int port) {
    if (origin_header.empty()) return true;
    const std::string o = lower(origin_header);
    return o.rfind("http://", 0) == 0 && host_allowed(o.substr(7), bound, port);
}

bool fetch_site_allowed(const std::string& sec_fetch_site) {
    return sec_fetch_site.empty() || sec_fetch_site == "same-origin" || sec_fetch_site == "none";
}

}  // namespace kerf::view
