#pragma once

namespace sortie::sim {

class SimNotifier;
class SimSessionTable;
class SimWorld;

// What the request handlers share: the world, the sessions, and the event publisher.
struct SimServices
{
    SimWorld &world;
    SimSessionTable &sessions;
    SimNotifier &notifier;
};

} // namespace sortie::sim
