package org.trajeval.pipeline.dir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Clock;
import java.time.Duration;
import java.util.stream.Stream;
import org.trajeval.pipeline.bundle.BareBag;
import org.trajeval.pipeline.bundle.BundleKind;
import org.trajeval.pipeline.bundle.BundleOpener;

/**
 * Decides, for one entry of incoming/, whether it is the key of a complete bundle. The key is
 * the marker ({@code NAME.done}); under {@link Completion#MARKER_OR_QUIET} also a folder, zip,
 * {@code NAME.est.csv} or bare bag ({@code NAME.mcap}, .bag, .db3) without a marker that has been
 * unchanged for the quiet time. Hidden and
 * temporary files are never keys.
 */
final class IncomingScanner {
    private final Path incoming;
    private final Completion completion;
    private final Duration quietTime;
    private final Clock clock;

    IncomingScanner(Path incoming, Completion completion, Duration quietTime, Clock clock) {
        this.incoming = incoming;
        this.completion = completion;
        this.quietTime = quietTime;
        this.clock = clock;
    }

    /** @return whether the name is hidden or temporary (never part of a bundle) */
    static boolean ignored(String name) {
        return name.startsWith(".") || name.startsWith("~") || name.endsWith("~") || name.endsWith(".tmp")
                || name.endsWith(".part") || name.endsWith(".partial") || name.endsWith(".crdownload")
                || name.endsWith(".swp");
    }

    /** @return whether the name could be the key of a bundle (cheap, no file system access) */
    boolean maybeKey(String name) {
        if (ignored(name)) {
            return false;
        }
        return name.endsWith(".done") || completion == Completion.MARKER_OR_QUIET;
    }

    /** @return the complete bundle whose key is {@code name}, or {@code null} */
    BundleUnit completeUnit(String name) {
        if (ignored(name)) {
            return null;
        }
        if (name.endsWith(".done")) {
            String base = name.substring(0, name.length() - ".done".length());
            if (base.isEmpty() || ignored(base)) {
                return null;
            }
            if (Files.isDirectory(incoming.resolve(base), LinkOption.NOFOLLOW_LINKS)) {
                return new BundleUnit(BundleKind.FOLDER, base, name);
            }
            if (base.endsWith(".zip") && Files.exists(incoming.resolve(base), LinkOption.NOFOLLOW_LINKS)) {
                return new BundleUnit(BundleKind.ZIP, base.substring(0, base.length() - 4), name);
            }
            if (Files.exists(incoming.resolve(base + ".zip"), LinkOption.NOFOLLOW_LINKS)) {
                return new BundleUnit(BundleKind.ZIP, base, name);
            }
            if (Files.exists(incoming.resolve(base + BundleOpener.PAIR_ESTIMATE), LinkOption.NOFOLLOW_LINKS)
                    || Files.exists(incoming.resolve(base + BundleOpener.PAIR_REFERENCE), LinkOption.NOFOLLOW_LINKS)) {
                return new BundleUnit(BundleKind.PAIR, base, name);
            }
            String bag = bareBag(base);
            if (bag != null) {
                return new BundleUnit(BundleKind.BAG, bag, name);
            }
            if (Files.exists(incoming.resolve(base), LinkOption.NOFOLLOW_LINKS)) {
                // a marker beside a single file that is no bundle: hand it on, it will be refused with the reason
                return new BundleUnit(BundleKind.FOLDER, base, name);
            }
            return null;
        }
        if (completion != Completion.MARKER_OR_QUIET) {
            return null;
        }
        Path p = incoming.resolve(name);
        BundleUnit unit;
        if (Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) {
            unit = new BundleUnit(BundleKind.FOLDER, name, null);
        } else if (name.endsWith(".zip")) {
            unit = new BundleUnit(BundleKind.ZIP, name.substring(0, name.length() - 4), null);
        } else if (BareBag.stem(name) != null) {
            unit = new BundleUnit(BundleKind.BAG, name, null);
        } else if (name.endsWith(BundleOpener.PAIR_ESTIMATE)) {
            unit = new BundleUnit(BundleKind.PAIR, name.substring(0, name.length() - BundleOpener.PAIR_ESTIMATE.length()),
                    null);
        } else {
            return null;
        }
        for (String marker : unit.candidateMarkers()) {
            if (Files.exists(incoming.resolve(marker), LinkOption.NOFOLLOW_LINKS)) {
                return null; // the marker is its key
            }
        }
        for (String part : unit.payloadNames()) {
            if (!quiet(incoming.resolve(part))) {
                return null;
            }
        }
        return unit;
    }

    /** @return the bare bag a marker {@code base.done} completes ({@code base} itself, or base.mcap/.bag/.db3), or null */
    private String bareBag(String base) {
        if (BareBag.stem(base) != null && Files.isRegularFile(incoming.resolve(base), LinkOption.NOFOLLOW_LINKS)) {
            return base;
        }
        for (String ext : BareBag.EXTENSIONS) {
            if (Files.isRegularFile(incoming.resolve(base + ext), LinkOption.NOFOLLOW_LINKS)) {
                return base + ext;
            }
        }
        return null;
    }

    private boolean quiet(Path p) {
        long newest;
        try (Stream<Path> s = Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS) ? Files.walk(p) : Stream.of(p)) {
            newest = s.mapToLong(IncomingScanner::mtime).max().orElse(Long.MAX_VALUE);
        } catch (IOException | java.io.UncheckedIOException e) {
            return false;
        }
        return newest != Long.MAX_VALUE && clock.millis() - newest >= quietTime.toMillis();
    }

    private static long mtime(Path p) {
        try {
            FileTime t = Files.getLastModifiedTime(p, LinkOption.NOFOLLOW_LINKS);
            return t.toMillis();
        } catch (IOException e) {
            return Long.MAX_VALUE;
        }
    }
}
