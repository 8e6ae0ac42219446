import QtQuick
import QtQuick.Controls
import QtQuick.Layouts
import Sortie.Ui

// Server, user and password, handed to `connection` (the client's connection controller). The
// controller decides how the password travels (TLS, or in clear after the question shown here).
Page {
    id: page
    required property AppSettings appSettings
    required property ClientGraph graph   // the client's services: this page uses the connection
    required property Theme theme
    readonly property ConnectionController connection: graph.connection
    property alias serverField: server
    property alias userField: user
    property alias passwordField: password

    readonly property bool connected: connection.state !== "Disconnected"

    signal connectRequested(string server, string user, string password)
    onConnectRequested: (server, user, password) => {
        page.connection.connectToServer(server, user, password)
    }

    // The keyring answers after the page is up: its password fills the field unless one was typed.
    Connections {
        target: page.appSettings
        function onPasswordRecalled() {
            if (password.text.length === 0)
                password.text = page.appSettings.password
        }
    }

    // A login made elsewhere (the demo, --server) shows where and as whom in the fields.
    Connections {
        target: page.connection
        function onStateChanged() {
            if (page.connected && page.connection.server.length > 0) {
                server.text = page.connection.server
                user.text = page.connection.user
            }
        }
    }

    // As wide as its longest words need (a longer language widens it), at least 420, at most the
    // page; narrower than its words, the title wraps and the check box elides.
    Frame {
        objectName: "loginFrame"
        anchors.centerIn: parent
        width: Math.min(parent.width - 40, Math.max(420, form.implicitWidth + leftPadding + rightPadding))
        padding: 24
        ColumnLayout {
            id: form
            anchors.fill: parent
            spacing: 10
            Label {
                textFormat: Text.PlainText
                objectName: "loginTitle"
                Layout.fillWidth: true
                wrapMode: Text.Wrap
                text: qsTr("Connect to a UgCS server")
                font.pixelSize: 20
                font.bold: true
            }
            Label { textFormat: Text.PlainText; text: qsTr("Server (host:port)") }
            TextField {
                id: server
                objectName: "serverField"
                Layout.fillWidth: true
                enabled: !page.connected
                // Filled once: a binding would overwrite what the operator typed whenever a setting changes.
                Component.onCompleted: text = page.appSettings.lastServer
                placeholderText: "localhost:3334"
                selectByMouse: true
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Host name or address and HCI port of the UgCS server")
            }
            CheckBox {
                id: secure
                objectName: "secureCheck"
                Layout.fillWidth: true
                enabled: !page.connected
                text: qsTr("Secure (TLS)")
                // The address says it (tls://host:port); the box only adds or takes off the prefix.
                checked: page.connection.isSecureAddress(server.text)
                onToggled: {
                    server.text = page.connection.withSecurity(server.text, checked)
                    checked = Qt.binding(() => page.connection.isSecureAddress(server.text))
                }
                ToolTip.visible: hovered
                ToolTip.text: qsTr("For a server behind a TLS terminator: the password and everything else travel encrypted")
            }
            Label { textFormat: Text.PlainText; text: qsTr("User") }
            TextField {
                id: user
                objectName: "userField"
                Layout.fillWidth: true
                enabled: !page.connected
                Component.onCompleted: text = page.appSettings.lastUser
                selectByMouse: true
            }
            Label { textFormat: Text.PlainText; text: qsTr("Password") }
            TextField {
                id: password
                objectName: "passwordField"
                Layout.fillWidth: true
                enabled: !page.connected
                echoMode: TextInput.Password
                Component.onCompleted: text = page.appSettings.rememberPassword ? page.appSettings.password : ""
                onAccepted: connectButton.clicked()
            }
            CheckBox {
                id: remember
                objectName: "rememberCheck"
                Layout.fillWidth: true
                text: qsTr("Remember the password on this computer")
                enabled: page.appSettings.canRememberPassword
                checked: page.appSettings.rememberPassword
                onToggled: page.appSettings.rememberPassword = checked
                ToolTip.visible: hovered
                ToolTip.text: qsTr("Kept in this computer's keyring for this server and user, never in a file")
            }
            Label {
                textFormat: Text.PlainText
                // No keyring (and why), a keyring that refused, a password moved out of the settings file.
                objectName: "rememberNotice"
                Layout.preferredWidth: 1 // a sentence wraps in the width the fields make; it does not widen the frame
                Layout.fillWidth: true
                wrapMode: Text.Wrap
                font.pixelSize: 12
                opacity: 0.8
                text: page.appSettings.passwordNotice
                visible: text.length > 0
            }
            RowLayout {
                Layout.fillWidth: true
                Button {
                    id: connectButton
                    objectName: "connectButton"
                    visible: !page.connected
                    text: qsTr("Connect")
                    highlighted: true
                    enabled: server.text.length > 0 && user.text.length > 0
                    onClicked: {
                        page.appSettings.rememberLogin(server.text, user.text, password.text)
                        page.connectRequested(server.text, user.text, password.text)
                    }
                    ToolTip.visible: hovered
                    ToolTip.text: qsTr("Log in (Enter in the password field)")
                }
                Button {
                    objectName: "disconnectButton"
                    visible: page.connected
                    text: qsTr("Disconnect")
                    onClicked: page.connection.disconnectFromServer()
                }
                BusyIndicator {
                    objectName: "busyIndicator"
                    running: page.connection.busy
                    visible: running
                    implicitWidth: 32
                    implicitHeight: 32
                }
                Item { Layout.fillWidth: true }
            }
            Label {
                textFormat: Text.PlainText
                objectName: "loginStatus"
                Layout.preferredWidth: 1 // a sentence wraps in the width the fields make; it does not widen the frame
                Layout.fillWidth: true
                wrapMode: Text.Wrap
                visible: page.connected
                text: page.connection.ready ? qsTr("Logged in as %1 at %2.").arg(page.connection.user).arg(page.connection.server)
                                            : qsTr("%1…").arg(page.connection.stateText)
            }
            Frame {
                // The password would go in clear to another computer: asked once per server.
                objectName: "cleartextQuestion"
                Layout.fillWidth: true
                visible: page.connection.askingCleartext
                ColumnLayout {
                    anchors.fill: parent
                    spacing: 8
                    Label {
                        objectName: "cleartextQuestionText"
                        Layout.preferredWidth: 1
                        Layout.fillWidth: true
                        wrapMode: Text.Wrap
                        textFormat: Text.PlainText
                        text: page.connection.cleartextQuestion
                    }
                    RowLayout {
                        Button {
                            objectName: "sendInClearButton"
                            text: qsTr("Send in clear")
                            onClicked: page.connection.answerCleartext(true)
                        }
                        Button {
                            objectName: "refuseCleartextButton"
                            text: qsTr("Do not connect")
                            highlighted: true
                            onClicked: page.connection.answerCleartext(false)
                        }
                    }
                }
            }
            Label {
                objectName: "certificateNote"
                Layout.preferredWidth: 1
                Layout.fillWidth: true
                wrapMode: Text.Wrap
                textFormat: Text.PlainText
                font.pixelSize: 12
                text: page.connection.certificateNote
                visible: text.length > 0
            }
            Label {
                textFormat: Text.PlainText
                objectName: "loginMessage"
                Layout.preferredWidth: 1 // a sentence wraps in the width the fields make; it does not widen the frame
                Layout.fillWidth: true
                wrapMode: Text.Wrap
                color: page.theme.problemText
                text: page.connection.errorString
                visible: text.length > 0
            }
        }
    }
}
