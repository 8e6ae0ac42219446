#pragma once

#include <memory>

namespace sortie::mission {

// The server's own object a value came from (a segment's, a route's, a mission's), kept beside it
// so that saving merges our edits into a copy of what the server sent, unknown fields included.
// An opaque token here: only mission/hci (HciOrigin.h) puts something in it or reads it, so the
// plan model carries no wire type. Provenance, not content: two values that differ only in origin
// compare equal.
class ServerOrigin
{
public:
    // What mission/hci keeps; the model neither reads nor copies its contents.
    struct Payload
    {
        virtual ~Payload() = default;
    };

    ServerOrigin() = default;
    explicit ServerOrigin(std::shared_ptr<const Payload> payload) : m_payload(std::move(payload)) {}

    const Payload *payload() const { return m_payload.get(); }
    explicit operator bool() const { return bool(m_payload); }
    bool operator==(const ServerOrigin &) const { return true; }

private:
    std::shared_ptr<const Payload> m_payload;
};

} // namespace sortie::mission
