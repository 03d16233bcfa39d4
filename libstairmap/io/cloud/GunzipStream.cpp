#include "io/cloud/GunzipStream.h"

#include <zlib.h>

#include <stdexcept>
#include <streambuf>
#include <vector>

namespace stairmap::io {

namespace {
constexpr int kGzipWindowBits = 15 + 16;  // zlib: +16 selects the gzip wrapper
constexpr std::size_t kChunk = 1 << 16;
}  // namespace

/// The inflating buffer behind GunzipStream: one output chunk at a time, on demand.
class GunzipStreamBuf : public std::streambuf {
public:
    GunzipStreamBuf(std::istream& source, std::size_t max_bytes)
        : source_(source), max_bytes_(max_bytes), in_(kChunk), out_(kChunk) {}
    ~GunzipStreamBuf() override {
        if (initialised_) inflateEnd(&z_);
    }
    const std::string& error() const { return error_; }

    /// Inflates the rest (discarding it); then the verdict on the whole stream.
    void finish() {
        while (underflow() != traits_type::eof()) setg(eback(), egptr(), egptr());
        if (!error_.empty()) throw std::runtime_error(error_);
        if (z_.avail_in != 0 || source_.peek() != std::char_traits<char>::eof())
            throw std::runtime_error("trailing data after the gzip stream");
    }

protected:
    int_type underflow() override {
        if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
        if (ended_ || !error_.empty()) return traits_type::eof();
        if (!initialised_ && !start()) return traits_type::eof();
        for (;;) {
            if (z_.avail_in == 0 && !fillInput()) return fail("truncated gzip data");
            z_.next_out = reinterpret_cast<Bytef*>(out_.data());
            z_.avail_out = static_cast<uInt>(out_.size());
            const int code = inflate(&z_, Z_NO_FLUSH);
            // Z_BUF_ERROR: no progress possible without more input (the loop refills).
            if (code != Z_OK && code != Z_STREAM_END && code != Z_BUF_ERROR) {
                return fail("corrupt gzip data (" +
                            std::string(z_.msg ? z_.msg : "zlib code " + std::to_string(code)) + ")");
            }
            ended_ = code == Z_STREAM_END;
            const std::size_t n = out_.size() - z_.avail_out;
            produced_ += n;
            if (produced_ > max_bytes_)
                return fail("decompresses to more than " + std::to_string(max_bytes_) + " bytes");
            if (n > 0) {
                setg(out_.data(), out_.data(), out_.data() + n);
                return traits_type::to_int_type(out_[0]);
            }
            if (ended_) return traits_type::eof();
        }
    }

private:
    int_type fail(std::string message) {
        error_ = std::move(message);
        setg(out_.data(), out_.data(), out_.data());
        return traits_type::eof();
    }

    /// Checks the signature and sets zlib up; false (with the error set) if not gzip.
    bool start() {
        fillInput();
        if (z_.avail_in < 2 || in_[0] != '\x1f' || in_[1] != '\x8b') {
            fail("not gzip data (no gzip signature 1f 8b)");
            return false;
        }
        if (inflateInit2(&z_, kGzipWindowBits) != Z_OK) {
            fail("zlib inflateInit2 failed");
            return false;
        }
        initialised_ = true;
        return true;
    }

    /// Next chunk of compressed bytes; false at the end of the source.
    bool fillInput() {
        source_.read(in_.data(), static_cast<std::streamsize>(in_.size()));
        const auto got = static_cast<std::size_t>(source_.gcount());
        z_.next_in = reinterpret_cast<Bytef*>(in_.data());
        z_.avail_in = static_cast<uInt>(got);
        return got > 0;
    }

    std::istream& source_;
    std::size_t max_bytes_;
    std::size_t produced_ = 0;  ///< decompressed bytes so far
    z_stream z_{};
    bool initialised_ = false;
    bool ended_ = false;  ///< the member ended with a valid CRC and length
    std::string error_;
    std::vector<char> in_, out_;
};

GunzipStream::GunzipStream(std::istream& source, std::size_t max_bytes)
    : std::istream(nullptr), buf_(std::make_unique<GunzipStreamBuf>(source, max_bytes)) {
    rdbuf(buf_.get());
}

GunzipStream::~GunzipStream() = default;

const std::string& GunzipStream::error() const { return buf_->error(); }

void GunzipStream::finish() { buf_->finish(); }

}  // namespace stairmap::io
