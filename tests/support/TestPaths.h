#pragma once
#include <QString>

// Where the tests find their files. PHONGLAB_SOURCE_DIR and
// PHONGLAB_TEST_DATA_DIR come from phonglab_test_support (tests/CMakeLists.txt).
namespace phonglab::test {

// <source tree>/<relative>: the shipped shaders, assets and docs.
inline QString sourcePath(const QString &relative)
{
    return QStringLiteral(PHONGLAB_SOURCE_DIR "/") + relative;
}

// tests/data/<relative>: scenes, meshes and shaders made for the tests.
inline QString testDataPath(const QString &relative)
{
    return QStringLiteral(PHONGLAB_TEST_DATA_DIR "/") + relative;
}

} // namespace phonglab::test
