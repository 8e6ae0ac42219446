#include "RouteConflict.h"

#include "HciOrigin.h"
#include "HciRouteMapper.h"
#include "Messages.pb.h"
#include "RouteDiff.h"

#include <QDateTime>

namespace sortie::client {

using namespace sortie::mission;
namespace pb = com::ugcs::ucs::proto;

RouteConflict::RouteConflict(QObject *parent)
    : QObject(parent)
{
}

RouteConflict::~RouteConflict() = default;

bool RouteConflict::set(const pb::Route &theirs, const Route &mine, const Route &common)
{
    auto imported = routeFromHci(theirs);
    if (!imported) {
        clear();
        return false;
    }
    m_theirs = std::make_unique<pb::Route>(theirs);
    m_changes = RouteDiff::compare(imported->route, mine).texts();
    // The version both started from is the one the document was opened at.
    m_yourVersion = mine.origin && hciRoute(mine.origin)->has_version() ? hciRoute(mine.origin)->version() : -1;
    m_yourEdits = RouteDiff::compare(common, mine).texts();
    m_theirEdits = RouteDiff::compare(common, imported->route).texts();
    m_model.resetRoute(std::move(imported->route));
    emit changed();
    return true;
}

void RouteConflict::clear()
{
    const bool was = isActive();
    m_theirs.reset();
    m_changes.clear();
    m_yourEdits.clear();
    m_theirEdits.clear();
    m_yourVersion = -1;
    m_model.resetRoute({});
    if (was)
        emit changed();
}

int RouteConflict::theirVersion() const
{
    return m_theirs ? m_theirs->version() : -1;
}

QDateTime RouteConflict::theirSaveTime() const
{
    return m_theirs && m_theirs->has_lastmodificationtime() ? QDateTime::fromMSecsSinceEpoch(m_theirs->lastmodificationtime(), Qt::UTC)
                                                            : QDateTime();
}

} // namespace sortie::client
