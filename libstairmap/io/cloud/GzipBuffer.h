#pragma once
// Whole-buffer gzip (RFC 1952) for small files such as compressed point clouds (.pcd.gz, ...).
// Strict: the reader accepts exactly one gzip member, complete and with a matching CRC; anything
// else (plain data, a truncated or corrupt stream, trailing bytes) is an error, never guessed at.
// Output is reproducible: no file name and a zero modification time in the header, so the same
// data and level give the same bytes (bundled datasets regenerate byte-identically).

#include <cstddef>
#include <string>

namespace stairmap::io {

/// Limit on the decompressed size (a guard against decompression bombs) [bytes].
constexpr std::size_t kMaxGunzipBytes = std::size_t{1} << 31;

/// Compresses `data` into one gzip member at `level` (1..9). Throws std::invalid_argument for a
/// bad level, std::runtime_error if zlib fails.
std::string gzipBuffer(const std::string& data, int level = 9);

/// Decompresses one gzip member. Throws std::runtime_error with the problem ("not gzip data",
/// "truncated gzip data", "corrupt gzip data (...)", "trailing data after the gzip stream",
/// "decompresses to more than ... bytes"); no path in the message.
std::string gunzipBuffer(const std::string& compressed, std::size_t max_bytes = kMaxGunzipBytes);

}  // namespace stairmap::io
