// Helper for tst_save_kill: saves two versions of a project over TARGET in turns,
// starting with the second, until it is killed. The versions are the documents the test
// built with projectJson (files A and B, read once at start so that startup is quick);
// each save is the atomic write saveProject ends with (writeFileAtomically), so nearly
// every moment of the loop is inside it. Before each save it prints "saving N" (N counts
// from 1) and flushes, so the test can aim its SIGKILL at a chosen save.
#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s TARGET A B\n", argv[0]);
        return 2;
    }
    const std::string documents[2] = {trimlab::io::readFileBytes(argv[2], std::size_t(1) << 30),
                                      trimlab::io::readFileBytes(argv[3], std::size_t(1) << 30)};
    for (unsigned long save = 1;; ++save) {
        std::printf("saving %lu\n", save);
        std::fflush(stdout);
        trimlab::io::writeFileAtomically(argv[1], documents[save % 2]);
    }
}
