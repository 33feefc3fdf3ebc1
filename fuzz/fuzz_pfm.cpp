// Fuzz target: PFM depth images through readPfm (io/pfm_image.h), which reads a path:
// the input is written to this process's scratch folder. readPfm documents
// std::runtime_error for bad files.
#include "fuzz_support.h"

#include "core/io/pfm_image.h"

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const auto path = trimlab::fuzz::writeScratchFile("fuzz.pfm", trimlab::fuzz::bytesOf(data, size));
    trimlab::fuzz::expectTypedErrors<std::runtime_error>([&] { (void)trimlab::io::readPfm(path); });
    return 0;
}
