#pragma once
#include "core/ResourcePaths.h"

#include <QByteArray>
#include <QFile>

#include <algorithm>
#include <cmath>
#include <vector>

// What the latency benchmarks share.
namespace phonglab::bench {

// The value at fraction p (0..1) of the sorted samples, nearest rank; 0 when empty.
inline double percentile(std::vector<double> v, double p)
{
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t rank = std::size_t(std::ceil(p * double(v.size())));
    return v[std::min(v.size() - 1, rank > 0 ? rank - 1 : 0)];
}

// The shipped Phong fragment shader with its output scaled by `k`: a new
// text, so a new program, for every k.
inline QByteArray editedFragment(double k)
{
    QFile file(shaderPath(QStringLiteral("phong.frag")));
    file.open(QIODevice::ReadOnly);
    QByteArray text = file.readAll();
    text.replace("fragColor = vec4(I, 1.0);",
                 "fragColor = vec4(I * " + QByteArray::number(k, 'f', 6) + ", 1.0);");
    return text;
}

} // namespace phonglab::bench
