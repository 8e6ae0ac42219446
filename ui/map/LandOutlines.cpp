#include "LandOutlines.h"

#include "WebMercator.h"

#include <QFile>
#include <QtEndian>
#include <QCoreApplication>

namespace sortie::ui {

namespace {

class Reader
{
public:
    explicit Reader(const QByteArray &data) : m_data(data) {}

    bool read(quint32 *value)
    {
        if (m_pos + 4 > size_t(m_data.size()))
            return false;
        *value = qFromLittleEndian<quint32>(m_data.constData() + m_pos);
        m_pos += 4;
        return true;
    }
    bool read(qint32 *value)
    {
        quint32 raw = 0;
        if (!read(&raw))
            return false;
        *value = qint32(raw);
        return true;
    }
    size_t position() const { return m_pos; }
    size_t remaining() const { return size_t(m_data.size()) - m_pos; }
    void skip(size_t bytes) { m_pos += bytes; }

private:
    const QByteArray &m_data;
    size_t m_pos = 0;
};

constexpr QByteArrayView kMagic = "SLAND001";

} // namespace

std::optional<LandOutlines> LandOutlines::fromData(const QByteArray &compressed, QString *error)
{
    const QByteArray data = qUncompress(compressed);
    if (data.isEmpty()) {
        *error = QCoreApplication::translate("LandOutlines", "the land outline file is not compressed data");
        return std::nullopt;
    }
    if (!data.startsWith(kMagic)) {
        *error = QCoreApplication::translate("LandOutlines", "the land outline file does not start with %1").arg(QLatin1String(kMagic.data()));
        return std::nullopt;
    }
    Reader reader(data);
    reader.skip(size_t(kMagic.size()));
    LandOutlines outlines;
    quint32 polygonCount = 0;
    if (!reader.read(&polygonCount) || polygonCount > reader.remaining() / 4) {
        *error = QCoreApplication::translate("LandOutlines", "the land outline file is truncated at its polygon count");
        return std::nullopt;
    }
    outlines.m_polygons.reserve(polygonCount);
    for (quint32 p = 0; p < polygonCount; ++p) {
        Polygon polygon;
        quint32 ringCount = 0;
        if (!reader.read(&ringCount) || ringCount > reader.remaining() / 4) {
            *error = QCoreApplication::translate("LandOutlines", "the land outline file is truncated in polygon %1").arg(p);
            return std::nullopt;
        }
        for (quint32 r = 0; r < ringCount; ++r) {
            quint32 pointCount = 0;
            if (!reader.read(&pointCount) || pointCount > reader.remaining() / 8) {
                *error = QCoreApplication::translate("LandOutlines", "the land outline file is truncated in polygon %1, ring %2").arg(p).arg(r);
                return std::nullopt;
            }
            std::vector<QPointF> ring;
            ring.reserve(pointCount);
            qint64 lon = 0;
            qint64 lat = 0;
            for (quint32 i = 0; i < pointCount; ++i) {
                qint32 dLon = 0;
                qint32 dLat = 0;
                reader.read(&dLon);
                reader.read(&dLat);
                lon += dLon;
                lat += dLat;
                ring.push_back(WebMercator::project(lat * 1e-5, lon * 1e-5));
            }
            outlines.m_points += ring.size();
            if (r == 0 && !ring.empty()) {
                double minX = ring[0].x(), maxX = minX, minY = ring[0].y(), maxY = minY;
                for (const QPointF &pt : ring) {
                    minX = std::min(minX, pt.x());
                    maxX = std::max(maxX, pt.x());
                    minY = std::min(minY, pt.y());
                    maxY = std::max(maxY, pt.y());
                }
                polygon.bounds = QRectF(QPointF(minX, minY), QPointF(maxX, maxY));
            }
            polygon.rings.push_back(std::move(ring));
        }
        if (!polygon.rings.empty() && polygon.rings.front().size() >= 3)
            outlines.m_polygons.push_back(std::move(polygon));
    }
    return outlines;
}

std::optional<LandOutlines> LandOutlines::fromResource(QString *error)
{
    QFile file(QString::fromLatin1(kResourcePath));
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QCoreApplication::translate("LandOutlines", "the built-in land outlines (%1) are missing").arg(file.fileName());
        return std::nullopt;
    }
    return fromData(file.readAll(), error);
}

} // namespace sortie::ui
