// A fresh folder tree for one test, removed afterwards (include and import
// tests write the files they read).
#pragma once
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace kerf::test {

struct TempTree {
    std::filesystem::path root;
    TempTree() {
        std::random_device rd;
        root = std::filesystem::temp_directory_path() / ("kerf_test_" + std::to_string(rd()) + std::to_string(rd()));
        std::filesystem::create_directories(root);
    }
    ~TempTree() {
        std::error_code ec;
        std::filesystem::remove_all(root, ec);
    }
    TempTree(const TempTree&) = delete;
    TempTree& operator=(const TempTree&) = delete;
    std::string write(const std::string& rel, const std::string& bytes) {
        std::filesystem::path p = root / rel;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << bytes;
        return p.string();
    }
    std::string path(const std::string& rel) const { return (root / rel).string(); }
};

}  // namespace kerf::test
