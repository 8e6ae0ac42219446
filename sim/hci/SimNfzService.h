#pragma once

namespace sortie::sim {

class HciRequestDispatcher;
class SimWorld;

// GetNfzListRequest: the store's no-fly zones (SimZones) whose extent meets the requested box
// (radians), of the requested types (none listed: both). Creating, changing and deleting custom
// zones goes through SimObjectService (CreateOrUpdateObject, DeleteObject, with its lock checks);
// SimNotifier tells environment subscribers EET_NFZ_UPDATED after each change.
class SimNfzService
{
public:
    static void install(HciRequestDispatcher &dispatcher, SimWorld &world);
};

} // namespace sortie::sim
