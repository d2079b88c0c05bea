// kerf view's HTTP server (docs/spec.md §13; cpp-httplib): one page, its
// event stream and the renders, on a loopback address only. Routes:
//   GET  /                 the page (page.html, compiled in)
//   GET  /events           server-sent events (event_hub.hpp)
//   GET  /image/ID.png     a render the session stored (the last few)
//   POST /camera?...       a new view (camera_text.hpp); 204, or 400
//   POST /reset            back to the scene's own camera; 204
// Anything else is 404; a request whose Host, Origin or Sec-Fetch-Site is
// not its own is 403 before any route runs (guard.hpp). It serves no file
// of the disk. The rendering side (cli/view_session) only calls publish()
// and put_image() and receives the handlers' calls.
#pragma once
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "csg/scene.hpp"

namespace kerf::view {

struct Handlers {
    std::function<void(const csg::Camera&)> camera;  // called on a server thread
    std::function<void()> reset;
};

// The server lives in a module, libkerf_view.so (server.cpp, with
// cpp-httplib and the OpenSSL and Brotli libraries it links, ~3 ms of
// every start when kerf linked them), opened by open_server() on the first
// `kerf view` (open_server.cpp; docs/performance.md, "Start-up").
class Server {
public:
    virtual ~Server() = default;  // stops serving and ends the event streams

    virtual int port() const = 0;
    virtual std::string url() const = 0;  // http://ADDRESS:PORT/
    // Starts answering on its own threads.
    virtual void start() = 0;
    // A server-sent event (kind, one line of JSON) for every open page.
    virtual void publish(const std::string& kind, const std::string& json) = 0;
    // Stores the bytes of a PNG as /image/ID.png; returns ID (from 1).
    virtual std::uint64_t put_image(std::vector<unsigned char> png) = 0;
};

// Binds `address` (refused unless loopback) on `port` (0: a free one).
// Throws std::runtime_error saying why it cannot, or that the module
// cannot be loaded.
std::unique_ptr<Server> open_server(const std::string& address, int port, Handlers handlers);

// The module's entry point, kerf_view_open_server: the server, or nullptr
// with `error` saying why (no exception crosses the module's boundary).
using OpenServer = Server* (*)(const std::string& address, int port, Handlers& handlers, std::string& error);

}  // namespace kerf::view
