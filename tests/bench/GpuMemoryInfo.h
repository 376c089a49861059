#pragma once
#include <QOpenGLContext>
#include <QOpenGLFunctions>

#include <cstdint>

// What the driver says about its own memory, where it says anything:
// GL_NVX_gpu_memory_info (NVIDIA) or GL_ATI_meminfo (AMD). Mesa's llvmpipe
// has neither: its "GPU memory" is this process's memory.
namespace phonglab::bench {

struct GpuMemoryInfo {
    std::int64_t totalBytes = -1;     // dedicated video memory; -1: not reported
    std::int64_t availableBytes = -1; // free now; -1: not reported
    const char *source = "none";
};

// Needs a current context.
inline GpuMemoryInfo queryGpuMemory()
{
    constexpr GLenum kDedicatedVidmemNvx = 0x9047, kCurrentAvailableNvx = 0x9049;
    constexpr GLenum kVboFreeMemoryAti = 0x87FB;
    GpuMemoryInfo info;
    QOpenGLContext *context = QOpenGLContext::currentContext();
    if (!context)
        return info;
    QOpenGLFunctions *gl = context->functions();
    if (context->hasExtension("GL_NVX_gpu_memory_info")) {
        GLint total = 0, available = 0; // KiB
        gl->glGetIntegerv(kDedicatedVidmemNvx, &total);
        gl->glGetIntegerv(kCurrentAvailableNvx, &available);
        info = {std::int64_t(total) * 1024, std::int64_t(available) * 1024,
                "GL_NVX_gpu_memory_info"};
    } else if (context->hasExtension("GL_ATI_meminfo")) {
        GLint free[4] = {}; // KiB: free, largest free block, free auxiliary, largest auxiliary
        gl->glGetIntegerv(kVboFreeMemoryAti, free);
        info = {-1, std::int64_t(free[0]) * 1024, "GL_ATI_meminfo"};
    }
    return info;
}

} // namespace phonglab::bench
