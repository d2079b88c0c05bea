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

class Server {
public:
    // Binds `address` (refused unless loopback) on `port` (0: a free one).
    // Throws std::runtime_error saying why it cannot.
    Server(const std::string& address, int port, Handlers handlers);
    ~Server();  // stops serving and ends the event streams
    Server(const Server&) = delete;
    Server& operator=(const Server&) = delete;

    int port() const;
    std::string url() const;  // http://ADDRESS:PORT/
    // Starts answering on its own threads.
    void start();
    // A server-sent event (kind, one line of JSON) for every open page.
    void publish(const std::string& kind, const std::string& json);
    // Stores the bytes of a PNG as /image/ID.png; returns ID (from 1).
    std::uint64_t put_image(std::vector<unsigned char> png);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace kerf::view
