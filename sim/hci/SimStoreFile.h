#pragma once

#include <QString>

namespace sortie::sim {

class SimObjectStore;

// Reads and writes the simulator's object store as a JSON file:
//   {"format": "sortie-sim-store", "version": 1, "nextId": N,
//    "objects": [{"type": "Route", "object": <DomainObjectWrapper as protobuf JSON>}, ...]}
// Errors name the file and the JSON path ("objects[3].object: ..."). Writes are atomic.
class SimStoreFile
{
public:
    static bool load(const QString &path, SimObjectStore &store, QString *error);
    static bool save(const QString &path, const SimObjectStore &store, QString *error);
};

} // namespace sortie::sim
