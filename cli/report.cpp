#include "cli/report.hpp"

#include <iostream>
#include <new>

#include "interpreter/interpreter.hpp"

namespace kerf::cli {

void print_warnings(const std::vector<Diagnostic>& warnings) {
    for (const auto& w : warnings) std::cerr << format_diagnostic(w) << '\n';
}

int report_failure(const std::exception_ptr& error) {
    try {
        std::rethrow_exception(error);
    } catch (const DefineError& e) {  // a broken -D value is a bad command line
        std::cerr << format_diagnostic(e.diagnostic()) << '\n';
        return kUsage;
    } catch (const SourceError& e) {
        std::cerr << format_diagnostic(e.diagnostic()) << '\n';
        return kSceneError;
    } catch (const IoError& e) {
        std::cerr << "kerf: error: " << e.what() << '\n';
        return kUsage;
    } catch (const std::bad_alloc&) {
        std::cerr << "kerf: error: out of memory\n";
        return kRenderFailed;
    } catch (const std::exception& e) {
        std::cerr << "kerf: error: " << e.what() << '\n';
        return kRenderFailed;
    }
}

}  // namespace kerf::cli
