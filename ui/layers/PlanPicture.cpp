#include "PlanPicture.h"

#include <QPaintDevice>
#include <QPainter>

#include <algorithm>

namespace sortie::ui {

namespace {
// Beyond the waypoints: the active ring (radius 14) and its pen.
constexpr qreal kReach = 17;
} // namespace

void PlanPicture::layOut(QPolygonF points)
{
    m_points = std::move(points);
    m_laidOut = true;
    m_valid = false;
}

void PlanPicture::invalidate()
{
    m_laidOut = false;
    m_valid = false;
}

void PlanPicture::paint(QPainter &painter, const Look &look, const QRectF &clip, qint64 *budget)
{
    if (m_points.isEmpty())
        return;
    QPaintDevice *device = painter.device();
    const qreal dpr = device ? device->devicePixelRatioF() : 1.0;
    if (m_valid && (m_image.isNull() || (look == m_look && m_image.devicePixelRatio() == dpr))) {
        *budget -= qint64(m_image.width()) * m_image.height();
        if (!m_image.isNull())
            painter.drawImage(m_origin, m_image);
        return;
    }
    ++m_redraws;
    m_look = look;
    const QRect bounds = m_points.boundingRect().adjusted(-kReach, -kReach, kReach, kReach).intersected(clip).toAlignedRect();
    const qint64 pixels = qint64(bounds.width() * dpr) * qint64(bounds.height() * dpr);
    if (bounds.isEmpty()) { // off the picture: nothing to show until the layout changes
        m_image = QImage();
        m_valid = true;
        return;
    }
    if (pixels > *budget) { // too big to keep: drawn as it is, and again next time
        m_image = QImage();
        m_valid = false;
        draw(painter, m_points, look, clip);
        return;
    }
    *budget -= pixels;
    m_image = QImage(QSize(int(bounds.width() * dpr), int(bounds.height() * dpr)), QImage::Format_ARGB32_Premultiplied);
    m_image.setDevicePixelRatio(dpr);
    m_image.fill(Qt::transparent);
    m_origin = bounds.topLeft();
    {
        QPainter onto(&m_image);
        onto.setFont(painter.font());
        onto.translate(-m_origin);
        draw(onto, m_points, look, clip);
    }
    m_valid = true;
    painter.drawImage(m_origin, m_image);
}

std::optional<QLineF> PlanPicture::clipped(const QLineF &line, const QRectF &rect)
{
    const double dx = line.dx(), dy = line.dy();
    double t0 = 0, t1 = 1;
    // Each edge: p * t <= q keeps the point inside.
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {line.x1() - rect.left(), rect.right() - line.x1(), line.y1() - rect.top(), rect.bottom() - line.y1()};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0) {
            if (q[i] < 0)
                return std::nullopt; // parallel to this edge and outside it
            continue;
        }
        const double t = q[i] / p[i];
        if (p[i] < 0)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        if (t0 > t1)
            return std::nullopt;
    }
    return QLineF(line.pointAt(t0), line.pointAt(t1));
}

void PlanPicture::draw(QPainter &painter, const QPolygonF &points, const Look &look, const QRectF &clip)
{
    painter.setRenderHint(QPainter::Antialiasing, true);
    const QColor done = look.done;
    // A waypoint is behind once the vehicle flies to a later one (or the mission is complete).
    auto behind = [&](int index) { return look.complete || (look.active >= 0 && index < look.active); };
    // Numbers for the chosen vehicle's waypoints only (text is the costly part); the others get
    // plain dots, and nothing off the picture is drawn.
    const QRectF picture = clip.adjusted(-12, -12, 12, 12);
    for (int i = 1; i < points.size(); ++i) {
        const auto leg = clipped(QLineF(points[i - 1], points[i]), picture);
        if (!leg)
            continue;
        painter.setPen(behind(i) ? QPen(done, 2, Qt::DashLine, Qt::RoundCap)
                                 : QPen(look.color, look.current ? 4 : 2.5, Qt::SolidLine, Qt::RoundCap));
        painter.drawLine(*leg);
    }
    for (int i = 0; i < points.size(); ++i) {
        if (!picture.contains(points[i]))
            continue;
        const bool isActive = i == look.active;
        const double radius = isActive ? 10 : look.numbered ? 8 : 4;
        if (isActive) {
            painter.setPen(QPen(look.attention, 3));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(points[i], radius + 4, radius + 4);
        }
        painter.setPen(QPen(look.outline, 1.5));
        painter.setBrush(behind(i) ? done : look.color);
        painter.drawEllipse(points[i], radius, radius);
        if (!look.numbered && !isActive)
            continue;
        painter.setPen(look.outline);
        painter.drawText(QRectF(points[i] - QPointF(radius, radius), QSizeF(2 * radius, 2 * radius)), Qt::AlignCenter,
                         QString::number(i + 1));
    }
}

} // namespace sortie::ui
