#include "Polyline.h"

#include <vector>

namespace sortie::ui {

QPolygonF simplifyPolyline(const QPolygonF &in, double tolerance)
{
    const qsizetype n = in.size();
    if (n < 3)
        return in;
    std::vector<bool> keep(size_t(n), false);
    keep.front() = keep.back() = true;
    std::vector<std::pair<qsizetype, qsizetype>> stack{{0, n - 1}};
    const double tolerance2 = tolerance * tolerance;
    while (!stack.empty()) {
        const auto [first, last] = stack.back();
        stack.pop_back();
        const QPointF a = in[first];
        const QPointF ab = in[last] - a;
        const double length2 = QPointF::dotProduct(ab, ab);
        double worst = -1;
        qsizetype worstIndex = -1;
        for (qsizetype i = first + 1; i < last; ++i) {
            const QPointF ap = in[i] - a;
            double d2;
            const double t = length2 > 0 ? QPointF::dotProduct(ap, ab) / length2 : 0.0;
            if (t <= 0) {
                d2 = QPointF::dotProduct(ap, ap);
            } else if (t >= 1) {
                const QPointF bp = in[i] - in[last];
                d2 = QPointF::dotProduct(bp, bp);
            } else {
                const double cross = ab.x() * ap.y() - ab.y() * ap.x();
                d2 = cross * cross / length2;
            }
            if (d2 > worst) {
                worst = d2;
                worstIndex = i;
            }
        }
        if (worst > tolerance2) {
            keep[size_t(worstIndex)] = true;
            stack.emplace_back(first, worstIndex);
            stack.emplace_back(worstIndex, last);
        }
    }
    QPolygonF out;
    for (qsizetype i = 0; i < n; ++i) {
        if (keep[size_t(i)])
            out.append(in[i]);
    }
    return out;
}

} // namespace sortie::ui
