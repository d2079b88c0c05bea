// Source files, locations and diagnostics: shared by every stage that can
// blame a line of a script. Locations hold a shared pointer to the file so
// the AST, the scene graph and csg::Scene all outlive the parse buffer.
#pragma once
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace kerf {

struct SourceFile {
    std::string path;  // as given by the user or resolved by include/use
    std::string text;  // whole file contents (for caret lines)
};

struct SourceLoc {
    std::shared_ptr<const SourceFile> file;  // null for command-line/synthetic
    std::uint32_t line = 0;                  // 1-based; 0 = unknown
    std::uint32_t col = 0;                   // 1-based, in bytes
};

enum class Severity { Error, Warning, Note };

struct Diagnostic {
    Severity severity = Severity::Error;
    SourceLoc loc;
    std::string message;
    std::uint64_t repeats = 1;  // a warning met again at the same place is one diagnostic
    // Where the place was reached from (Severity::Note, "in 'f' called from
    // here"), innermost first, as compilers print instantiation chains.
    std::vector<Diagnostic> notes;
};

// "PATH:LINE:COL: error: MESSAGE" followed, when the text is known, by the
// source line and a caret under the column (docs/spec.md §8), then each note
// in the same form. No trailing newline.
std::string format_diagnostic(const Diagnostic& d);

// The one-line head only ("PATH:LINE:COL: error: MESSAGE"; a repeated
// warning ends in " (N times)"), without the notes.
std::string format_diagnostic_head(const Diagnostic& d);

// The thrown form of a user-caused error: parse, evaluation and lowering
// errors all end up here, so the CLI has one catch and one exit code.
class SourceError : public std::runtime_error {
public:
    explicit SourceError(Diagnostic d) : std::runtime_error(std::string()), diag_(std::move(d)) {}
    SourceError(SourceLoc loc, std::string message)
        : SourceError(Diagnostic{Severity::Error, std::move(loc), std::move(message), 1, {}}) {}
    // The head line, formatted when first asked: the OpenSCAD dialect
    // throws and catches a SoftError for every warning of a built-in, and
    // formatting each was a sixth of that (10^6 sqrt("a"): 2.5 s user
    // before, 2.1 s; docs/openscad.md).
    const char* what() const noexcept override {
        try {
            if (what_.empty()) what_ = format_diagnostic_head(diag_);
            return what_.c_str();
        } catch (...) {
            return "error (out of memory formatting it)";
        }
    }
    const Diagnostic& diagnostic() const noexcept { return diag_; }
    // The call-site notes, added once by the innermost call the error
    // leaves (the interpreter's call stack is gone by the time it is caught).
    bool has_call_notes() const noexcept { return noted_; }
    void set_call_notes(std::vector<Diagnostic> notes) {
        diag_.notes = std::move(notes);
        noted_ = true;
    }
    // Everything the run reported, in order (its warnings, then every
    // error, the first being diagnostic()), when it went on after an error
    // to find more; empty when diagnostic() is all there is to print.
    std::vector<Diagnostic> reported;

private:
    Diagnostic diag_;
    bool noted_ = false;
    mutable std::string what_;
};

}  // namespace kerf
