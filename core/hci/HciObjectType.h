#pragma once

#include "HciProto.h"

#include <QString>

#include <optional>

namespace sortie::hci {

// The domain object types the client works with. On the wire an object type is the protobuf message
// name ("Vehicle", "Route"...), and objects travel in a DomainObjectWrapper whose field of that type is set.
enum class HciObjectType { Vehicle, Route, Mission, VehicleProfile, User, TraverseAlgorithm, CommandDefinition, RoutePass, NoFlightZone };

QString objectTypeName(HciObjectType type);
std::optional<HciObjectType> objectTypeFromName(const QString &name);

// True when `name` is a domain object type a DomainObjectWrapper can carry ("Route", "Platform"...).
bool isObjectType(const QString &name);
// Wraps any domain object (Route, Vehicle, ...) in a DomainObjectWrapper. Returns false when the wrapper
// has no field of the object's type.
bool wrapObject(const google::protobuf::Message &object, pb::DomainObjectWrapper *wrapper);
// The object a wrapper carries (the first field set), or nullptr when it is empty.
const google::protobuf::Message *unwrapObject(const pb::DomainObjectWrapper &wrapper);
// The object of the given type name ("Route") in a wrapper, or nullptr.
const google::protobuf::Message *unwrapObject(const pb::DomainObjectWrapper &wrapper, const QString &objectType);
// The object's `id` field, or -1 when it has none set.
int objectId(const google::protobuf::Message &object);

} // namespace sortie::hci
