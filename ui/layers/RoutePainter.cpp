#include "RoutePainter.h"

#include <QPainter>

namespace sortie::ui {

namespace {
constexpr int kMaxCachedNumbers = 20000;
}

const QStaticText &RoutePainter::number(int value)
{
    auto it = m_numbers.find(value);
    if (it == m_numbers.end()) {
        if (m_numbers.size() > kMaxCachedNumbers)
            m_numbers.clear();
        QStaticText text(QString::number(value));
        text.setTextFormat(Qt::PlainText);
        text.setPerformanceHint(QStaticText::AggressiveCaching);
        text.prepare(QTransform(), m_font);
        it = m_numbers.insert(value, text);
    }
    return it.value();
}

void RoutePainter::paint(QPainter &painter, const RouteFrame &frame, const Style &style)
{
    if (!m_fontReady) {
        m_font = painter.font();
        m_font.setPixelSize(int(style.markerRadius * 1.1));
        m_font.setBold(true);
        m_fontReady = true;
    }
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setBrush(Qt::NoBrush);
    QPen halo(style.halo, style.legWidth + 3.0, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
    painter.setPen(halo);
    for (const QPolygonF &leg : frame.legs)
        painter.drawPolyline(leg);
    painter.setPen(QPen(style.leg, style.legWidth, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    for (const QPolygonF &leg : frame.legs)
        painter.drawPolyline(leg);

    const double r = style.markerRadius;
    const QPen outline(style.halo, 1.5);
    painter.setFont(m_font);
    for (const RouteFrame::Marker &marker : frame.markers) {
        const bool selected = marker.flags & RouteFrame::Selected;
        const bool current = marker.flags & RouteFrame::Current;
        const QColor fill = selected ? style.selected : style.marker;
        if (!(marker.flags & RouteFrame::Labelled)) {
            painter.setPen(outline);
            painter.setBrush(fill);
            painter.drawEllipse(marker.position, r * 0.4, r * 0.4);
            continue;
        }
        if (current) {
            painter.setPen(QPen(style.current, 3.0));
            painter.setBrush(Qt::NoBrush);
            painter.drawEllipse(marker.position, r + 4, r + 4);
        }
        const QStaticText &text = number(marker.row + 1);
        const QSizeF size = text.size();
        const double w = std::max(2 * r, size.width() + 6);
        painter.setPen(outline);
        painter.setBrush(fill);
        painter.drawRoundedRect(QRectF(marker.position - QPointF(w / 2, r), QSizeF(w, 2 * r)), r, r);
        painter.setPen(style.text);
        painter.drawStaticText(marker.position - QPointF(size.width() / 2, size.height() / 2), text);
    }
}

} // namespace sortie::ui
