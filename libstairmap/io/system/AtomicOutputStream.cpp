#include "io/system/AtomicOutputStream.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "io/system/AtomicFile.h"

namespace stairmap::io {

AtomicOutputStream::AtomicOutputStream(std::string path)
    : path_(std::move(path)), tmp_(uniqueTempPath(path_)) {
    out_.open(tmp_, std::ios::binary | std::ios::trunc);
    if (!out_) {
        throw std::runtime_error(path_ + ": cannot create temporary file " + tmp_ + ": " +
                                 std::strerror(errno));
    }
}

AtomicOutputStream::~AtomicOutputStream() {
    if (committed_) return;
    out_.close();
    ::unlink(tmp_.c_str());
}

void AtomicOutputStream::commit() {
    out_.flush();
    const bool written = static_cast<bool>(out_);
    out_.close();
    try {
        if (!written || !out_) throw std::runtime_error("write failed");
        syncFile(tmp_);
        renameDurably(tmp_, path_);
    } catch (const std::exception& e) {
        ::unlink(tmp_.c_str());
        committed_ = true;  // nothing left to clean up
        throw std::runtime_error(path_ + ": " + e.what() + " (previous file left unchanged)");
    }
    committed_ = true;
}

}  // namespace stairmap::io
