#pragma once
// An input stream over bytes in memory: the readers of a texture's header and texels read the bytes hexc read once
// (hexc/image.h, TextureFile) as they would read the file, seeks included.
#include <istream>
#include <streambuf>
#include <string_view>

namespace hexc {

class MemoryBuffer : public std::streambuf {
public:
    explicit MemoryBuffer(std::string_view bytes) {
        char* begin = const_cast<char*>(bytes.data());  // only read: a streambuf's get area is not const
        setg(begin, begin, begin + bytes.size());
    }

protected:
    pos_type seekoff(off_type off, std::ios_base::seekdir dir, std::ios_base::openmode) override {
        const off_type size = egptr() - eback();
        const off_type at = (dir == std::ios_base::beg ? 0 : dir == std::ios_base::cur ? gptr() - eback() : size) + off;
        if (at < 0 || at > size) return pos_type(off_type(-1));
        setg(eback(), eback() + at, egptr());
        return pos_type(at);
    }
    pos_type seekpos(pos_type pos, std::ios_base::openmode which) override { return seekoff(off_type(pos), std::ios_base::beg, which); }
};

// The buffer is a base before std::istream, so that it exists when the stream is given it.
class MemoryStream : private MemoryBuffer, public std::istream {
public:
    explicit MemoryStream(std::string_view bytes) : MemoryBuffer(bytes), std::istream(static_cast<MemoryBuffer*>(this)) {}
};

}  // namespace hexc
