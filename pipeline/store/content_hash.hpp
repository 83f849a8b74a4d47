#pragma once
// A 64-bit content hash (FNV-1a) for telling whether a shot's inputs or a
// journal line changed.  Not cryptographic: it guards against accidents
// (an edited script, a torn write), not against an adversary.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace lc::farm {

class ContentHash {
 public:
  // Feeds bytes; order matters.
  ContentHash& add(std::string_view bytes);
  // Feeds a number as 8 little-endian bytes, so "1" + "23" and "12" + "3"
  // differ when lengths are added before strings.
  ContentHash& add(std::uint64_t value);
  std::uint64_t value() const { return h_; }
  // 16 lowercase hex digits.
  std::string hex() const;

 private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

// Hash of a whole string (e.g. a journal line).
std::uint64_t hash_bytes(std::string_view bytes);

// Hash of a regular file's content; throws std::runtime_error naming the
// file when it cannot be read or is no regular file (a FIFO, a device).
std::uint64_t hash_file(const std::filesystem::path& file);

// 16 lowercase hex digits.
std::string to_hex(std::uint64_t value);

}  // namespace lc::farm
