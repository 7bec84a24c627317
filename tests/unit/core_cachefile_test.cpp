// core/CacheFile: the one reader/writer of the start-up caches (embedded data, atmosphere
// tables, sky maps). Every damaged file is rejected with its reason and never crashes (also run
// under AddressSanitizer/UBSan: scripts/test.sh).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/CacheFile.hpp"
#include "support/RunBinary.hpp"

namespace fs = std::filesystem;
using og::core::readCacheFile;
using og::core::writeCacheFile;

namespace {

constexpr std::uint64_t kKey = 0x0123456789abcdefull;

std::vector<std::uint8_t> payload() {
  std::vector<std::uint8_t> p(10000);
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = static_cast<std::uint8_t>(i * 7 + 3);
  return p;
}

bool never(const std::string&) { return false; }

/// The reason `file` is rejected ("" when it is read back intact).
std::string rejection(const fs::path& file, std::uint64_t key = kKey) {
  std::string why;
  const auto read = readCacheFile(file, key, &why);
  if (read) {
    EXPECT_EQ(std::vector<std::uint8_t>(read->bytes().begin(), read->bytes().end()), payload());
    return "";
  }
  EXPECT_FALSE(why.empty());
  return why;
}

void patch(const fs::path& file, std::streamoff at, const void* bytes, std::size_t n) {
  std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(at);
  f.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(n));
}

}  // namespace

TEST(CacheFile, RoundTripsAndRejectsEveryDamageWithoutCrashing) {
  const fs::path dir = og::test::scratchDir("cachefile");
  const fs::path file = dir / "sub" / "x.bin";  // the directory is created
  writeCacheFile(file, kKey, payload(), never);
  const auto size = fs::file_size(file);
  ASSERT_EQ(size, 32 + payload().size());
  EXPECT_EQ(rejection(file), "");
  EXPECT_EQ(rejection(dir / "none.bin"), "missing");
  EXPECT_EQ(rejection(file, kKey + 1), "stale key");

  auto fresh = [&] { writeCacheFile(file, kKey, payload(), never); };
  fs::resize_file(file, size - 1);  // truncated payload
  EXPECT_EQ(rejection(file), "size field disagrees with the file's size");
  fresh();
  fs::resize_file(file, 20);  // truncated header
  EXPECT_EQ(rejection(file), "truncated header");
  fs::resize_file(file, 0);
  EXPECT_EQ(rejection(file), "truncated header");
  fresh();
  patch(file, 0, "NOTOURS!", 8);  // wrong magic
  EXPECT_EQ(rejection(file), "not an oceanglobe cache file");
  fresh();
  patch(file, 32 + 5000, "\x5a", 1);  // one payload byte
  EXPECT_EQ(rejection(file), "CRC mismatch");
  fresh();
  patch(file, 28, "\x01", 1);  // the reserved word does not matter
  EXPECT_EQ(rejection(file), "");
  for (const std::uint64_t huge : {std::uint64_t{~0ull}, std::uint64_t{1} << 62, std::uint64_t{size}}) {
    fresh();
    patch(file, 16, &huge, sizeof huge);  // a size field asking for far more than the file holds
    EXPECT_EQ(rejection(file), "size field disagrees with the file's size") << huge;
  }
  fresh();
  {
    std::ofstream(file, std::ios::app | std::ios::binary) << "trailing";
  }
  EXPECT_EQ(rejection(file), "size field disagrees with the file's size");
  fs::remove(file);
  fs::create_directory(file);  // a directory where the file should be
  std::string why;
  EXPECT_FALSE(readCacheFile(file, kKey, &why));
  EXPECT_EQ(why, "not a regular file");
}

TEST(CacheFile, APayloadOutlivesItsFileBeingReplacedOrRemoved) {
  // The payload is the file mapped into memory: the writer's rename of a new file over it, and
  // the removal of a superseded one, must leave what was read intact.
  const fs::path dir = og::test::scratchDir("cachefile");
  const fs::path file = dir / "x.bin";
  writeCacheFile(file, kKey, payload(), never);
  auto read = readCacheFile(file, kKey);
  ASSERT_TRUE(read);
  writeCacheFile(file, kKey, std::vector<std::uint8_t>(50, 0xee), never);
  auto moved = std::move(*read);  // moving keeps the mapping
  EXPECT_EQ(read->size(), 0u);
  ASSERT_EQ(moved.size(), payload().size());
  EXPECT_EQ(std::vector<std::uint8_t>(moved.bytes().begin(), moved.bytes().end()), payload());
  fs::remove(file);
  EXPECT_EQ(moved.bytes()[9999], payload()[9999]);
  EXPECT_EQ(rejection(file), "missing");
  // An empty payload round-trips (a header alone), and a FIFO in the file's place is refused
  // without hanging the open.
  writeCacheFile(file, kKey, {}, never);
  const auto empty = readCacheFile(file, kKey);
  ASSERT_TRUE(empty);
  EXPECT_EQ(empty->size(), 0u);
  fs::remove(file);
  ASSERT_EQ(::mkfifo(file.c_str(), 0600), 0);
  std::string why;
  EXPECT_FALSE(readCacheFile(file, kKey, &why));
  EXPECT_EQ(why, "not a regular file");
}

TEST(CacheFile, WritingRemovesOnlySupersededFiles) {
  const fs::path dir = og::test::scratchDir("cachefile");
  for (const char* name : {"a-old.bin", "a-other.bin", "b-old.bin"}) writeCacheFile(dir / name, kKey, payload(), never);
  writeCacheFile(dir / "a-new.bin", kKey, payload(), [](const std::string& f) { return f.rfind("a-", 0) == 0 && f != "a-other.bin"; });
  EXPECT_FALSE(fs::exists(dir / "a-old.bin"));
  EXPECT_TRUE(fs::exists(dir / "a-other.bin"));
  EXPECT_TRUE(fs::exists(dir / "b-old.bin"));
  EXPECT_EQ(rejection(dir / "a-new.bin"), "");
  // Rewriting a file never removes the file itself, even when the rule matches it.
  writeCacheFile(dir / "a-new.bin", kKey, payload(), [](const std::string&) { return true; });
  EXPECT_EQ(rejection(dir / "a-new.bin"), "");
  EXPECT_FALSE(fs::exists(dir / "b-old.bin"));
  // Nothing left behind under a temporary name.
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
}
