#pragma once
// OpenMesh's headers, included with OpenMesh's own asserts off. PhongLab's
// asserts are live in every build (CMakePresets.json), but OpenMesh's
// templates check each property access by building two std::string type
// names on the heap and comparing them: with those live, decimating the
// builtin sphere took over a minute under ASan and QtTest's watchdog ended
// unit.tst_meshdecimation in CI. assert() expands where a template is
// written, not where it is used, so NDEBUG around these includes turns off
// exactly OpenMesh's and leaves ours on after them.
//
// Every file includes OpenMesh through here (unit.openmeshincludes keeps it):
// an inline OpenMesh function compiled once with its asserts and once
// without would be two definitions of one function, and the linker keeps
// either. Only OpenMesh/Core/System/config.h, which holds nothing but the
// version macros, may be included on its own.
#ifndef NDEBUG
#define PHONGLAB_OPENMESH_ASSERTS_OFF
#define NDEBUG
#endif
#include <cassert>

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/Options.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/Mesh/BaseKernel.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModBaseT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Decimater/Observer.hh>

#ifdef PHONGLAB_OPENMESH_ASSERTS_OFF
#undef NDEBUG
#undef PHONGLAB_OPENMESH_ASSERTS_OFF
#endif
#include <cassert> // assert() as the build has it, for the includer's own code
