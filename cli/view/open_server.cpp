// open_server(): the HTTP server from its module, libkerf_view.so
// (server.hpp), opened on the first call.
#include <stdexcept>
#include <string>

#include "cli/view/server.hpp"
#include "csg/modules.hpp"

namespace kerf::view {

std::unique_ptr<Server> open_server(const std::string& address, int port, Handlers handlers) {
    // Loaded once: a throwing initialiser leaves it unset, tried again next call.
    static const OpenServer open = [] {
        std::string why;
        if (void* h = csg::open_module(KERF_VIEW_MODULE_NAME, KERF_VIEW_MODULE_PATH, &why)) {
            why.clear();
            if (auto f = csg::module_entry<OpenServer>(h, "kerf_view_open_server", &why)) return f;
        }
        throw std::runtime_error(csg::module_error("kerf view", KERF_VIEW_MODULE_NAME, why));
    }();
    std::string error;
    std::unique_ptr<Server> server(open(address, port, handlers, error));
    if (!server) throw std::runtime_error(error);
    return server;
}

}  // namespace kerf::view
