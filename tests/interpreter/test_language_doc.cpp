// Keeps docs/language.md true: every ```sdl block in it is evaluated (with
// the real stdlib search path). A block runs without error unless it
// contains `// error: TEXT`, in which case evaluation must fail with a
// diagnostic whose one-line head contains TEXT. Every `// ECHO: ...`
// comment in a block is an expected echo line, in order, and then the
// block's echo output must be exactly those lines.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>
#include <vector>

#include "interpreter/interpreter.hpp"
#include "tests/scripts/expectations.hpp"

using namespace kerf;

namespace {

struct Snippet {
    std::string code;
    unsigned line;  // of the opening fence, for failure messages
};

std::vector<Snippet> sdl_blocks(const std::string& path) {
    std::ifstream in(path);
    REQUIRE(in);
    std::vector<Snippet> out;
    std::string line;
    unsigned n = 0;
    bool inside = false;
    while (std::getline(in, line)) {
        ++n;
        if (!inside && line == "```sdl") {
            inside = true;
            out.push_back({"", n});
        } else if (inside && line == "```") {
            inside = false;
        } else if (inside) {
            out.back().code += line + "\n";
        }
    }
    CHECK_FALSE(inside);  // an unterminated fence
    return out;
}

}  // namespace

TEST_CASE("every sdl example in docs/language.md does what the text says", "[doc]") {
    auto blocks = sdl_blocks(KERF_SOURCE_DIR "/docs/language.md");
    CHECK(blocks.size() >= 20);
    for (const Snippet& b : blocks) {
        INFO("docs/language.md block at line " << b.line << ":\n" << b.code);
        auto file = std::make_shared<SourceFile>();
        file->path = KERF_SOURCE_DIR "/docs/example.sdl";
        file->text = b.code;
        std::vector<std::string> echoed;
        EvalOptions opt;
        opt.echo = [&](const std::string& l) { echoed.push_back(l); };
        std::vector<std::string> expected_echo;
        for (const std::string& e : test::markers(b.code, "// ECHO: ")) expected_echo.push_back("ECHO: " + e);
        auto errors = test::markers(b.code, "// error: ");
        if (errors.empty()) {
            CHECK_NOTHROW(evaluate_source(file, opt));
        } else {
            std::string got = "no error";
            try {
                evaluate_source(file, opt);
            } catch (const SourceError& e) {
                got = format_diagnostic_head(e.diagnostic());
            }
            CHECK_THAT(got, Catch::Contains(errors.front()));
        }
        if (!expected_echo.empty() || errors.empty()) CHECK(echoed == expected_echo);
    }
}
