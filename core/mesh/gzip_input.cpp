#include "core/mesh/gzip_input.h"

#include "core/mesh/mesh_load_error.h"
#include "core/util/memory_budget.h"

#include <zlib.h>

#include <algorithm>
#include <climits>
#include <cstdint>
#include <new>
#include <string>

namespace trimlab {

namespace {

// Owns an inflate stream for gzip input; ends it on every exit path.
class InflateStream {
public:
    explicit InflateStream(const std::string& displayName)
    {
        if (inflateInit2(&m_stream, 16 + MAX_WBITS) != Z_OK)
            throw MeshLoadError(displayName, "cannot initialise zlib for gzip input (out of memory?)");
    }
    ~InflateStream() { inflateEnd(&m_stream); }
    InflateStream(const InflateStream&) = delete;
    InflateStream& operator=(const InflateStream&) = delete;

    z_stream* get() { return &m_stream; }

private:
    z_stream m_stream{};
};

std::string formatBytes(std::size_t bytes)
{
    if (bytes >= (std::size_t(1) << 30) && bytes % (std::size_t(1) << 30) == 0)
        return std::to_string(bytes >> 30) + " GiB";
    return std::to_string(bytes) + " bytes";
}

bool allZero(std::string_view bytes)
{
    return std::all_of(bytes.begin(), bytes.end(), [](char c) { return c == '\0'; });
}

// Makes room for more output, never beyond maxOutputBytes + 1 (one byte past the cap is
// how we notice the cap is exceeded).
void growOutput(std::string& out, std::size_t produced, std::size_t maxOutputBytes, const std::string& displayName)
{
    const std::size_t limit = maxOutputBytes == SIZE_MAX ? SIZE_MAX : maxOutputBytes + 1;
    if (produced > maxOutputBytes || out.size() >= limit)
        throw MeshLoadError(displayName, "the gzip data decompresses to more than " + formatBytes(maxOutputBytes) +
                                             ", the limit for a mesh file; is it really a mesh?");
    const std::size_t wanted = std::min(std::max<std::size_t>(out.size() * 2, std::size_t(1) << 16), limit);
    // Growing copies: the old and the new buffer are alive at once.
    try {
        requireMemory(std::uint64_t(wanted) + out.size(),
                      "decompressing the gzip data (" + std::to_string(produced) + " bytes so far)",
                      "decompress the file separately to see its size");
        out.resize(wanted);
    } catch (const MemoryBudgetError& e) {
        throw MeshLoadError(displayName, e.what());
    } catch (const std::bad_alloc&) {
        throw MeshLoadError(displayName,
                            "out of memory decompressing the gzip data after " + std::to_string(produced) + " bytes");
    }
}

} // namespace

bool hasGzipMagic(std::string_view bytes)
{
    return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
           static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string gunzip(std::string_view compressed, const std::string& displayName, std::size_t maxOutputBytes)
{
    InflateStream inflater(displayName);
    z_stream* zs = inflater.get();
    std::string out;
    std::size_t produced = 0;
    std::size_t fed = 0; // bytes of `compressed` handed to zlib so far
    for (;;) {
        if (zs->avail_in == 0 && fed < compressed.size()) {
            const std::size_t chunk = std::min<std::size_t>(compressed.size() - fed, UINT_MAX);
            zs->next_in = reinterpret_cast<Bytef*>(const_cast<char*>(compressed.data() + fed));
            zs->avail_in = static_cast<uInt>(chunk);
            fed += chunk;
        }
        if (produced == out.size())
            growOutput(out, produced, maxOutputBytes, displayName);
        const std::size_t room = std::min<std::size_t>(out.size() - produced, UINT_MAX);
        zs->next_out = reinterpret_cast<Bytef*>(out.data() + produced);
        zs->avail_out = static_cast<uInt>(room);
        const int status = inflate(zs, Z_NO_FLUSH);
        produced += room - zs->avail_out;
        if (produced > maxOutputBytes)
            growOutput(out, produced, maxOutputBytes, displayName); // throws
        const std::size_t unread = zs->avail_in + (compressed.size() - fed);
        if (status == Z_STREAM_END) {
            const std::string_view rest = compressed.substr(compressed.size() - unread);
            if (unread == 0 || allZero(rest))
                break;
            if (!hasGzipMagic(rest))
                throw MeshLoadError(displayName,
                                    "unexpected " + std::to_string(unread) + " bytes after the end of the gzip data");
            inflateReset(zs); // another gzip member follows
            continue;
        }
        if (status == Z_BUF_ERROR && unread == 0)
            throw MeshLoadError(displayName, "truncated gzip data: it ends after " + std::to_string(produced) +
                                                 " decompressed bytes; the file is incomplete");
        if (status == Z_DATA_ERROR || status == Z_NEED_DICT || status == Z_STREAM_ERROR)
            throw MeshLoadError(displayName, std::string("corrupt gzip data (") +
                                                 (zs->msg ? zs->msg : "invalid deflate stream") + ")");
        if (status == Z_MEM_ERROR)
            throw MeshLoadError(displayName, "out of memory while decompressing gzip data");
    }
    out.resize(produced);
    return out;
}

} // namespace trimlab
