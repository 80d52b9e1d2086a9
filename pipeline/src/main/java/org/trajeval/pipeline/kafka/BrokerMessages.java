package org.trajeval.pipeline.kafka;

import org.apache.kafka.common.errors.AuthorizationException;
import org.apache.kafka.common.errors.SaslAuthenticationException;
import org.apache.kafka.common.errors.SslAuthenticationException;

/** One-line descriptions of broker problems for logs, /health and exit messages (never a secret). */
final class BrokerMessages {
    private BrokerMessages() {
    }

    /** @return "ExceptionName: first line of its message" */
    static String shortReason(Throwable t) {
        String m = t.getMessage() == null ? "" : t.getMessage().lines().findFirst().orElse("");
        if (m.length() > 200) {
            m = m.substring(0, 200) + "...";
        }
        return t.getClass().getSimpleName() + (m.isEmpty() ? "" : ": " + m);
    }

    /** @return why the broker refused this client, naming the broker, mechanism and user */
    static String refused(KafkaClients clients, Throwable cause) {
        String who = clients.identity();
        String what;
        if (cause instanceof SaslAuthenticationException) {
            what = "SASL authentication failed (" + who + "); check the user name and password";
        } else if (cause instanceof SslAuthenticationException) {
            what = "the TLS handshake failed (" + who + "); check the truststore (does it hold the broker's CA?), "
                    + "the broker's host name and, for mutual TLS, the keystore";
        } else if (cause instanceof AuthorizationException) {
            what = "not authorised (" + who + "); the broker's ACLs must allow this principal";
        } else {
            what = "authentication failed (" + who + ")";
        }
        return clients.scrub("Kafka broker " + clients.bootstrapServers() + " refused the connection: " + what + " ["
                + shortReason(cause) + "]");
    }
}
