#include "timeline/frame_export.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace trimlab::timeline {

namespace {

std::string objText(const std::vector<glm::vec3>& positions, const std::vector<glm::uvec3>& triangles)
{
    std::string text;
    text.reserve(positions.size() * 40 + triangles.size() * 24);
    char line[128];
    for (const glm::vec3& p : positions) {
        // %.9g: nine significant digits identify every float uniquely.
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", double(p.x), double(p.y), double(p.z));
        text += line;
    }
    for (const glm::uvec3& t : triangles) {
        std::snprintf(line, sizeof line, "f %u %u %u\n", t.x + 1, t.y + 1, t.z + 1);
        text += line;
    }
    return text;
}

void writeText(const std::filesystem::path& path, const std::string& text)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(text.data(), std::streamsize(text.size()));
    out.close();
    if (!out)
        throw std::runtime_error("cannot write " + path.string() + ": " + std::strerror(errno));
}

std::string frameFileName(const std::string& baseName, int f)
{
    char number[16];
    std::snprintf(number, sizeof number, "%04d", f);
    return baseName + "_" + number + ".obj";
}

} // namespace

std::vector<std::filesystem::path> exportObjSequence(const Timeline& timeline, const std::filesystem::path& directory,
                                                     const std::string& baseName)
{
    if (baseName.empty() || baseName.find_first_of("/\\") != std::string::npos)
        throw std::invalid_argument("exportObjSequence: the base name '" + baseName +
                                    "' must be a non-empty file name without folders");
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
        throw std::runtime_error("cannot create the folder " + directory.string() + ": " + error.message());
    std::vector<std::filesystem::path> written;
    // Walk the history once instead of reconstructing every frame from the base.
    std::vector<glm::vec3> positions = timeline.base().positions;
    for (int f = 0; f < timeline.frameCount(); ++f) {
        if (f > 0) {
            const Frame& frame = timeline.frame(f);
            for (std::size_t k = 0; k < frame.vertices.size(); ++k)
                positions[frame.vertices[k]] = frame.after[k];
        }
        const std::filesystem::path path = directory / frameFileName(baseName, f);
        writeText(path, objText(positions, timeline.base().triangles));
        written.push_back(path);
    }
    return written;
}

} // namespace trimlab::timeline
