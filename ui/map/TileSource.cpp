#include "TileSource.h"

namespace sortie::ui {

TileSource::TileSource(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<TileKey>();
}

void TileSource::setInfo(const QString &name, const QString &attribution, int minimumZoom, int maximumZoom)
{
    if (name == m_name && attribution == m_attribution && minimumZoom == m_minimumZoom && maximumZoom == m_maximumZoom)
        return;
    m_name = name;
    m_attribution = attribution;
    m_minimumZoom = minimumZoom;
    m_maximumZoom = maximumZoom;
    emit infoChanged();
}

void TileSource::setName(const QString &name)
{
    setInfo(name, m_attribution, m_minimumZoom, m_maximumZoom);
}

void TileSource::setAttribution(const QString &attribution)
{
    setInfo(m_name, attribution, m_minimumZoom, m_maximumZoom);
}

void TileSource::setMinimumZoomLevel(int zoom)
{
    setInfo(m_name, m_attribution, zoom, m_maximumZoom);
}

void TileSource::setMaximumZoomLevel(int zoom)
{
    setInfo(m_name, m_attribution, m_minimumZoom, zoom);
}

void TileSource::setReachable(bool reachable, const QString &errorString)
{
    if (reachable == m_reachable && errorString == m_errorString)
        return;
    m_reachable = reachable;
    m_errorString = errorString;
    emit reachableChanged();
}

} // namespace sortie::ui
