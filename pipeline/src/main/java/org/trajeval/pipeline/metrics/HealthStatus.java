package org.trajeval.pipeline.metrics;

import java.util.Objects;

/**
 * What {@code GET /health} answers: UP (200) or DOWN (503) with a reason a person can act on.
 *
 * @param up whether the service is doing its work
 * @param reason why it is down (empty when up)
 */
public record HealthStatus(boolean up, String reason) {
    /** The healthy answer. */
    public static final HealthStatus UP = new HealthStatus(true, "");

    /** @throws NullPointerException on a null reason */
    public HealthStatus {
        Objects.requireNonNull(reason, "reason");
    }

    /** @return a DOWN answer with its reason */
    public static HealthStatus down(String reason) {
        return new HealthStatus(false, reason);
    }

    /** @return the JSON body: {@code {"status":"UP"}} or {@code {"status":"DOWN","reason":"..."}} */
    public String json() {
        if (up) {
            return "{\"status\":\"UP\"}\n";
        }
        StringBuilder b = new StringBuilder("{\"status\":\"DOWN\",\"reason\":\"");
        for (char c : reason.toCharArray()) {
            switch (c) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                default -> {
                    if (c < 0x20) {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        return b.append("\"}\n").toString();
    }
}
