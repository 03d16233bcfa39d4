#include "io/cloud/GzipBuffer.h"

#include <zlib.h>

#include <stdexcept>

namespace stairmap::io {

namespace {
constexpr int kGzipWindowBits = 15 + 16;  // zlib: +16 selects the gzip wrapper
constexpr std::size_t kChunk = 1 << 16;

std::string zlibMessage(const z_stream& z, int code) {
    return z.msg ? z.msg : ("zlib code " + std::to_string(code));
}
}  // namespace

std::string gzipBuffer(const std::string& data, int level) {
    if (level < 1 || level > 9) throw std::invalid_argument("gzip level must be 1..9");
    if (data.size() > kMaxGunzipBytes) throw std::runtime_error("too large to gzip in one buffer");
    z_stream z{};
    if (deflateInit2(&z, level, Z_DEFLATED, kGzipWindowBits, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        throw std::runtime_error("zlib deflateInit2 failed");
    std::string out(deflateBound(&z, static_cast<uLong>(data.size())), '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
    z.avail_in = static_cast<uInt>(data.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    const int code = deflate(&z, Z_FINISH);  // deflateBound guarantees one call suffices
    const std::size_t written = z.total_out;
    deflateEnd(&z);
    if (code != Z_STREAM_END) throw std::runtime_error("gzip compression failed");
    out.resize(written);
    return out;
}

std::string gunzipBuffer(const std::string& compressed, std::size_t max_bytes) {
    if (compressed.size() < 2 || static_cast<unsigned char>(compressed[0]) != 0x1f ||
        static_cast<unsigned char>(compressed[1]) != 0x8b)
        throw std::runtime_error("not gzip data (no gzip signature 1f 8b)");
    if (compressed.size() > kMaxGunzipBytes)  // zlib counts input in 32-bit words
        throw std::runtime_error("compressed data larger than " + std::to_string(kMaxGunzipBytes) + " bytes");
    z_stream z{};
    if (inflateInit2(&z, kGzipWindowBits) != Z_OK) throw std::runtime_error("zlib inflateInit2 failed");
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data()));
    z.avail_in = static_cast<uInt>(compressed.size());
    std::string out;
    int code = Z_OK;
    while (code != Z_STREAM_END) {
        const std::size_t before = out.size();
        out.resize(before + kChunk);
        z.next_out = reinterpret_cast<Bytef*>(out.data() + before);
        z.avail_out = static_cast<uInt>(kChunk);
        code = inflate(&z, Z_NO_FLUSH);
        out.resize(before + kChunk - z.avail_out);
        if (code == Z_BUF_ERROR || (code == Z_OK && z.avail_in == 0 && z.avail_out != 0)) {
            inflateEnd(&z);
            throw std::runtime_error("truncated gzip data");
        }
        if (code != Z_OK && code != Z_STREAM_END) {
            const std::string message = zlibMessage(z, code);
            inflateEnd(&z);
            throw std::runtime_error("corrupt gzip data (" + message + ")");
        }
        if (out.size() > max_bytes) {
            inflateEnd(&z);
            throw std::runtime_error("decompresses to more than " + std::to_string(max_bytes) + " bytes");
        }
    }
    const bool trailing = z.avail_in != 0;
    inflateEnd(&z);
    if (trailing) throw std::runtime_error("trailing data after the gzip stream");
    return out;
}

}  // namespace stairmap::io
