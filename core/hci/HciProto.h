#pragma once

// Forward declarations of the generated HCI protobuf types the client headers name, so that including
// a client header does not pull in 6 MB of generated declarations. Include "Messages.pb.h" to use them.
namespace google::protobuf {
class Message;
class Descriptor;
} // namespace google::protobuf

namespace com::ugcs::ucs::proto {
class Command;
class DomainObjectWrapper;
class Error;
class ErrorDetailWrapper;
class EventSubscriptionWrapper;
class EventWrapper;
class Notification;
class OperationStatus;
class ProcessedRoute;
class Route;
class User;
class Vehicle;
} // namespace com::ugcs::ucs::proto

namespace sortie::hci {
namespace pb = com::ugcs::ucs::proto;
} // namespace sortie::hci
