package org.trajeval.pipeline.kafka;

import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.LongSupplier;
import org.apache.kafka.clients.admin.Admin;
import org.apache.kafka.common.errors.AuthenticationException;
import org.apache.kafka.common.errors.AuthorizationException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.trajeval.pipeline.metrics.HealthStatus;
import org.trajeval.pipeline.metrics.PipelineMetrics;

/**
 * Watches the broker from its own thread (an admin request every {@link #INTERVAL}): whether it
 * answers, whether the service's topics are still there ({@link TopicKeeper}), and whether
 * transactions commit. Logs one line per change of state ("unreachable since ...", "back after
 * ... s"), feeds the metrics and answers {@code /health}: DOWN with the reason once the broker
 * has been unreachable, or commits have failed, for longer than {@code unhealthyAfter}.
 */
public final class BrokerWatch implements AutoCloseable {
    /** Pause between two checks. */
    static final Duration INTERVAL = Duration.ofSeconds(2);
    private static final Logger LOG = LoggerFactory.getLogger(BrokerWatch.class);
    private static final long[] BACK_OFF_S = {1, 2, 4, 8, 15, 30};

    private final KafkaClients clients;
    private final TopicKeeper keeper;
    private final PipelineMetrics metrics;
    private final Clock clock;
    private final Duration unhealthyAfter;
    private final LongSupplier runsHeld;
    private final CountDownLatch stopped = new CountDownLatch(1);
    private final AtomicReference<String> republishTo = new AtomicReference<>();
    private final Object republishLock = new Object();
    private volatile Admin admin;
    private volatile Instant unreachableSince;
    private volatile String unreachableReason = "";
    private volatile Instant commitFailingSince;
    private volatile String commitReason = "";
    private volatile String refusal;
    private Thread thread;

    /**
     * @param clients builds the admin client
     * @param keeper keeps the topics
     * @param metrics where broker reachability goes
     * @param clock wall clock (log lines, health)
     * @param unhealthyAfter grace time before /health says DOWN
     * @param runsHeld runs scored and not committed (for the log line)
     */
    public BrokerWatch(KafkaClients clients, TopicKeeper keeper, PipelineMetrics metrics, Clock clock,
            Duration unhealthyAfter, LongSupplier runsHeld) {
        this.clients = clients;
        this.keeper = keeper;
        this.metrics = metrics;
        this.clock = clock;
        this.unhealthyAfter = unhealthyAfter;
        this.runsHeld = runsHeld;
    }

    /**
     * Waits until the broker answers, with back-off (1, 2, 4, 8, 15, then 30 s), one log line per
     * attempt; then makes sure the topics exist.
     *
     * @param timeout how long to wait; zero: forever
     * @return false when stopped while waiting
     * @throws BrokerFailure UNREACHABLE after the timeout, REFUSED at once when the broker refuses this client
     */
    public boolean awaitBroker(Duration timeout) throws InterruptedException {
        Instant start = clock.instant();
        for (int attempt = 1; ; attempt++) {
            String problem = checkOnce(true);
            if (problem == null) {
                return true;
            }
            if (refusal != null) {
                throw new BrokerFailure(BrokerFailure.Kind.REFUSED, clients.bootstrapServers(), refusal);
            }
            long waitS = BACK_OFF_S[Math.min(attempt - 1, BACK_OFF_S.length - 1)];
            Duration waited = Duration.between(start, clock.instant());
            if (!timeout.isZero() && waited.plusSeconds(waitS).compareTo(timeout) > 0) {
                throw new BrokerFailure(BrokerFailure.Kind.UNREACHABLE, clients.bootstrapServers(),
                        "no Kafka broker answered at " + clients.bootstrapServers() + " within " + timeout.toSeconds()
                                + " s (--startup-timeout; last problem: " + problem + ")");
            }
            LOG.warn("waiting for the Kafka broker at {} (attempt {}: {}); next attempt in {} s",
                    clients.bootstrapServers(), attempt, problem, waitS);
            if (stopped.await(waitS, TimeUnit.SECONDS)) {
                return false;
            }
        }
    }

    /** Starts the periodic checks on a daemon thread. */
    public void start() {
        thread = new Thread(() -> {
            try {
                while (!stopped.await(INTERVAL.toMillis(), TimeUnit.MILLISECONDS)) {
                    checkOnce(false);
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "trajeval-broker-watch");
        thread.setDaemon(true);
        thread.start();
    }

    /** @return null when the broker answered (and the topics are in place), else the problem */
    String checkOnce(boolean starting) throws InterruptedException {
        String problem;
        try {
            Admin a = admin();
            a.describeCluster().nodes().get(KafkaClients.ADMIN_TIMEOUT_MS + 1000L, TimeUnit.MILLISECONDS);
            synchronized (republishLock) {
                keeper.check(a).ifPresent(republishTo::set);
            }
            problem = null;
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            if (cause instanceof AuthenticationException || cause instanceof AuthorizationException) {
                refusal = BrokerMessages.refused(clients, cause);
            }
            problem = BrokerMessages.shortReason(cause);
        } catch (TimeoutException e) {
            problem = "no answer within " + (KafkaClients.ADMIN_TIMEOUT_MS / 1000) + " s";
        } catch (RuntimeException e) {
            problem = BrokerMessages.shortReason(e);
        }
        if (problem == null) {
            reachable(starting);
        } else if (!starting) {
            unreachable(problem);
        }
        return problem;
    }

    private Admin admin() {
        if (admin == null) {
            admin = clients.admin();
        }
        return admin;
    }

    private void reachable(boolean starting) {
        metrics.brokerReachable().set(1);
        refusal = null;
        Instant since = unreachableSince;
        if (since != null) {
            unreachableSince = null;
            LOG.info("broker {} back after {} s, resumed", clients.bootstrapServers(),
                    Duration.between(since, clock.instant()).toSeconds());
        } else if (starting) {
            LOG.info("connected to the Kafka broker at {}", clients.bootstrapServers());
        }
    }

    private void unreachable(String problem) {
        metrics.brokerReachable().set(0);
        unreachableReason = problem;
        if (unreachableSince == null) {
            unreachableSince = clock.instant();
            LOG.warn("broker {} unreachable since {} ({}); {} runs held, retrying", clients.bootstrapServers(),
                    unreachableSince.truncatedTo(ChronoUnit.SECONDS), problem, runsHeld.getAsLong());
        }
    }

    /** Notes a committed transaction. */
    public void commitSucceeded() {
        metrics.lastCommitMillis().set(clock.millis());
        commitFailingSince = null;
    }

    /** Notes a failed transaction (the first failure of a streak starts the clock). */
    public void commitFailed(String reason) {
        commitReason = reason;
        if (commitFailingSince == null) {
            commitFailingSince = clock.instant();
        }
    }

    /** Notes that the broker refused this client (health says so until it accepts again). */
    public void refused(String message) {
        refusal = message;
    }

    /** @return the new output topic id when every report must be published again */
    public Optional<String> republishNeeded() {
        return Optional.ofNullable(republishTo.get());
    }

    /** Notes that every report was published again to the topic with this id. */
    public void republished(String topicId) {
        synchronized (republishLock) { // a check in between would see the old id and ask again
            keeper.remember(topicId);
            if (topicId.equals(republishTo.get())) { // equals, not compareAndSet: each check makes a new String
                republishTo.set(null);
            }
        }
    }

    /** @return what /health answers */
    public HealthStatus health() {
        Instant now = clock.instant();
        if (refusal != null) {
            return HealthStatus.down(refusal);
        }
        Instant u = unreachableSince;
        if (u != null && Duration.between(u, now).compareTo(unhealthyAfter) > 0) {
            return HealthStatus.down("broker " + clients.bootstrapServers() + " unreachable since "
                    + u.truncatedTo(ChronoUnit.SECONDS) + " (" + unreachableReason + ")");
        }
        Instant c = commitFailingSince;
        if (c != null && Duration.between(c, now).compareTo(unhealthyAfter) > 0) {
            return HealthStatus.down("Kafka transactions failing since " + c.truncatedTo(ChronoUnit.SECONDS) + " ("
                    + commitReason + ")");
        }
        return HealthStatus.UP;
    }

    /** Stops the checks (and a start-up wait). */
    public void stop() {
        stopped.countDown();
    }

    @Override
    public void close() {
        stop();
        if (thread != null) {
            try {
                thread.join(KafkaClients.ADMIN_TIMEOUT_MS * 2L);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        Admin a = admin;
        if (a != null) {
            a.close(Duration.ofSeconds(1));
        }
    }
}
