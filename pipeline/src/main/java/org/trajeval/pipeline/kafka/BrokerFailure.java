package org.trajeval.pipeline.kafka;

/**
 * The broker cannot be used: unreachable within the start-up timeout, or it refuses this client
 * (credentials, certificates, permissions). The launcher prints the message (never a secret) and
 * exits with {@link Kind#exitCode()}.
 */
public final class BrokerFailure extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** What went wrong, with its documented exit code. */
    public enum Kind {
        /** No broker answered within the start-up timeout (exit 5). */
        UNREACHABLE(5),
        /** Authentication, TLS or authorisation refused (exit 6). */
        REFUSED(6);

        private final int exitCode;

        Kind(int exitCode) {
            this.exitCode = exitCode;
        }

        /** @return the launcher's exit code */
        public int exitCode() {
            return exitCode;
        }
    }

    private final Kind kind;
    private final String bootstrapServers;

    /**
     * @param kind what went wrong
     * @param bootstrapServers the broker address
     * @param message one line naming the broker and what to do (no secret)
     */
    public BrokerFailure(Kind kind, String bootstrapServers, String message) {
        super(message);
        this.kind = kind;
        this.bootstrapServers = bootstrapServers;
    }

    /** @return what went wrong */
    public Kind kind() {
        return kind;
    }

    /** @return the broker address */
    public String bootstrapServers() {
        return bootstrapServers;
    }
}
