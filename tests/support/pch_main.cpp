// The executable that makes the precompiled <QtTest> the tests of its Qt modules reuse
// (tests/CMakeLists.txt); it runs nothing.
int main()
{
    return 0;
}
