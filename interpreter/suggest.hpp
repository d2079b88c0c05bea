// "did you mean 'width'?" for a misspelled name (docs/spec.md §13): the
// closest offered name by edit distance, if it is close enough to be a
// likely typo (at most a third of the name's letters, rounded up; names
// shorter than three letters get no suggestion).
// Only built on the error path.
#pragma once
#include <string>
#include <string_view>

namespace kerf::eval {

class Suggestion {
public:
    explicit Suggestion(std::string_view wanted) : wanted_(wanted) {}
    void offer(std::string_view name);
    // "; did you mean 'NAME'?" or "" when nothing is close.
    std::string text() const;

private:
    std::string_view wanted_;
    std::string best_;
    std::size_t distance_ = static_cast<std::size_t>(-1);
};

}  // namespace kerf::eval
