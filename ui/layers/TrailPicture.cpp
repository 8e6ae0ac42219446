#include "TrailPicture.h"

#include <QPaintDevice>
#include <QPainter>

namespace sortie::ui {

void TrailPicture::restart(std::vector<Stroke> strokes)
{
    m_pending = std::move(strokes);
    m_restart = true;
}

void TrailPicture::add(Stroke stroke)
{
    m_pending.push_back(std::move(stroke));
}

void TrailPicture::stroke(QPainter &painter, const std::vector<Stroke> &strokes) const
{
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setBrush(Qt::NoBrush);
    for (const Stroke &s : strokes) {
        if (s.line.size() < 2)
            continue;
        painter.setPen(QPen(s.color, width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter.drawPolyline(s.line);
    }
}

void TrailPicture::paint(QPainter &painter, qreal opacity)
{
    QPaintDevice *device = painter.device();
    const QSize size = device ? QSize(device->width(), device->height()) : QSize();
    const qreal dpr = device ? device->devicePixelRatioF() : 1.0;
    if (m_image.size() != size || m_image.devicePixelRatio() != dpr) {
        // A new device size comes with a new layout: whatever is pending is all there is.
        m_image = QImage(size, QImage::Format_ARGB32_Premultiplied);
        m_image.setDevicePixelRatio(dpr);
        m_restart = true;
    }
    if (m_restart)
        m_image.fill(Qt::transparent);
    if (m_restart || !m_pending.empty()) {
        QPainter onto(&m_image);
        stroke(onto, m_pending);
    }
    m_pending.clear();
    m_restart = false;
    painter.save();
    painter.setOpacity(opacity);
    painter.drawImage(QPointF(0, 0), m_image);
    painter.restore();
}

} // namespace sortie::ui
