package org.trajeval.pipeline.bundle;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.options.SettingValues;
import org.trajeval.pipeline.CoreRunScorer;
import org.trajeval.pipeline.RunFailure;
import org.trajeval.pipeline.RunJob;
import org.trajeval.pipeline.RunMetadata;
import org.trajeval.pipeline.Stage;
import org.trajeval.pipeline.StageException;

/**
 * Opens a claimed bundle and returns the run it holds, with both trajectory paths checked to lie
 * inside the bundle (no absolute paths, no {@code ..}, no symbolic links) and within the size limits.
 */
public final class BundleOpener {
    /** Suffix of a bare pair's reference file. */
    public static final String PAIR_REFERENCE = ".gt.csv";
    /** Suffix of a bare pair's estimate file. */
    public static final String PAIR_ESTIMATE = ".est.csv";

    private final BundleLimits limits;
    private final SettingValues bagSettings;

    /** @param limits size limits; bare bags are refused (no topics configured) */
    public BundleOpener(BundleLimits limits) {
        this(limits, SettingValues.DEFAULTS);
    }

    /**
     * @param limits size limits
     * @param bagSettings the settings bare bags are scored with (the configuration's {@code bags.metrics}:
     *     {@code ref_topic} and {@code est_topic} at least, else bare bags are refused with the reason)
     */
    public BundleOpener(BundleLimits limits, SettingValues bagSettings) {
        this.limits = limits;
        this.bagSettings = java.util.Objects.requireNonNull(bagSettings, "bagSettings");
    }

    /**
     * Opens a bundle.
     *
     * @param kind folder, zip, pair or bare bag
     * @param payload the folder, the zip file, the folder holding the pair's two files, or the bag file
     * @param name the bundle's name (folder name, zip name without .zip, the pair's NAME, or the bag's file name)
     * @param scratch an empty folder a zip may be extracted into
     * @throws StageException with stage UNPACK or MANIFEST and the reason
     */
    public RunJob open(BundleKind kind, Path payload, String name, Path scratch) {
        return switch (kind) {
            case FOLDER -> {
                rejectLink(payload, name);
                yield openFolder(payload.toAbsolutePath().normalize(), name);
            }
            case ZIP -> {
                rejectLink(payload, name);
                try {
                    ZipExtractor.extract(payload, scratch, name + ".zip", limits);
                } catch (InputException e) {
                    throw new StageException(RunFailure.of(Stage.UNPACK, e), e);
                }
                yield openFolder(manifestFolder(scratch.toAbsolutePath().normalize(), name), name + ".zip");
            }
            case PAIR -> openPair(payload, name);
            case BAG -> {
                rejectLink(payload, name);
                RunMetadata metadata;
                try {
                    metadata = RunMetadata.ofName(BareBag.stem(name));
                } catch (InputException e) {
                    InputException named = new InputException(name, 0, "name", e.problem(),
                            "a bare bag's NAME is its run id: " + e.detail(), name, e);
                    throw new StageException(RunFailure.of(Stage.UNPACK, named), named);
                }
                yield openBag(payload, metadata, name);
            }
        };
    }

    /**
     * Opens a bare bag (dropped alone, or named by a run event): one file that is both the reference
     * and the estimate, read with the configured {@code bags.metrics} (its {@code ref_topic} and
     * {@code est_topic}).
     *
     * @param bag the bag file
     * @param metadata the run's identity (NAME of NAME.mcap, or the event's)
     * @param source how to name the run in messages and the report
     * @throws StageException MANIFEST when no topics are configured, UNPACK on a link, a missing or
     *     oversized file
     */
    public RunJob openBag(Path bag, RunMetadata metadata, String source) {
        if (!bagSettings.has(org.trajeval.core.options.Setting.REF_TOPIC)
                || !bagSettings.has(org.trajeval.core.options.Setting.EST_TOPIC)) {
            InputException e = new InputException(source, 0, "bags.metrics", InputProblem.INVALID_CONFIGURATION,
                    "a bare bag is scored with the topics of the service configuration: set bags.metrics.ref_topic and "
                            + "bags.metrics.est_topic (or send the bag in a bundle with its run.yaml)", null);
            throw new StageException(RunFailure.of(Stage.MANIFEST, e), e);
        }
        try {
            Path file = SafePaths.requireRegularFile(bag, source, "bag", source, limits.maxFileBytes());
            RunJob job = new RunJob(metadata, file, file, bagSettings, source);
            CoreRunScorer.readOptions(job, org.trajeval.core.options.FileRole.REFERENCE, limits.maxFileBytes());
            CoreRunScorer.readOptions(job, org.trajeval.core.options.FileRole.ESTIMATE, limits.maxFileBytes());
            return job;
        } catch (InputException e) {
            throw new StageException(RunFailure.of(Stage.UNPACK, e), e);
        }
    }

    /**
     * Resolves a bundle location (from a run event) under {@code base}: relative, no {@code ..},
     * no symbolic link on the way, an existing folder or .zip file.
     *
     * @throws InputException PATH_ESCAPES or UNREADABLE naming the field {@code bundle}
     */
    public static Path locate(Path base, String location, String source) {
        Path root = base.toAbsolutePath().normalize();
        if (location == null || location.isBlank()) {
            throw new InputException(source, 0, "bundle", InputProblem.INVALID_CONFIGURATION,
                    "bundle must name a folder or .zip under the bundle base", location);
        }
        String r = location.replace('\\', '/');
        if (r.startsWith("/") || Path.of(location).isAbsolute()) {
            throw new InputException(source, 0, "bundle", InputProblem.PATH_ESCAPES,
                    "bundle must be a path relative to the bundle base, not an absolute path", location);
        }
        for (String part : r.split("/")) {
            if (part.equals("..")) {
                throw new InputException(source, 0, "bundle", InputProblem.PATH_ESCAPES,
                        "bundle must stay inside the bundle base ('..' is not allowed)", location);
            }
        }
        Path p = root.resolve(r).normalize();
        for (Path q = p; q != null && q.startsWith(root) && !q.equals(root); q = q.getParent()) {
            if (Files.isSymbolicLink(q)) {
                throw new InputException(source, 0, "bundle", InputProblem.PATH_ESCAPES,
                        "bundle must not go through a symbolic link", location);
            }
        }
        if (!p.startsWith(root) || !Files.exists(p, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
            throw new InputException(source, 0, "bundle", InputProblem.UNREADABLE,
                    "bundle must name an existing folder or .zip under the bundle base", location);
        }
        return p;
    }

    private RunJob openFolder(Path dir, String source) {
        RunManifest manifest;
        try {
            manifest = RunManifest.read(dir.resolve(RunManifest.FILE_NAME), source + "/" + RunManifest.FILE_NAME,
                    Math.min(limits.maxFileBytes(), 1 << 20));
        } catch (InputException e) {
            throw new StageException(RunFailure.of(Stage.MANIFEST, e), e);
        }
        String manifestName = source + "/" + RunManifest.FILE_NAME;
        try {
            Path ref = SafePaths.resolveFile(dir, manifest.reference(), manifestName, "reference", limits.maxFileBytes());
            Path est = SafePaths.resolveFile(dir, manifest.estimate(), manifestName, "estimate", limits.maxFileBytes());
            RunJob job = new RunJob(manifest.metadata(), ref, est, manifest.settings(), source, dir,
                    manifest.plot());
            CoreRunScorer.readOptions(job, org.trajeval.core.options.FileRole.REFERENCE, limits.maxFileBytes());
            CoreRunScorer.readOptions(job, org.trajeval.core.options.FileRole.ESTIMATE, limits.maxFileBytes());
            return job;
        } catch (InputException e) {
            throw new StageException(RunFailure.of(Stage.UNPACK, e), e);
        }
    }

    private RunJob openPair(Path dir, String name) {
        try {
            RunMetadata metadata;
            try {
                metadata = RunMetadata.ofName(name);
            } catch (InputException e) {
                throw new InputException(name + PAIR_REFERENCE, 0, "name", e.problem(),
                        "a bare pair's NAME is its run id: " + e.detail(), name, e);
            }
            Path ref = SafePaths.requireRegularFile(dir.resolve(name + PAIR_REFERENCE), name + PAIR_REFERENCE,
                    "reference", name + PAIR_REFERENCE, limits.maxFileBytes());
            Path est = SafePaths.requireRegularFile(dir.resolve(name + PAIR_ESTIMATE), name + PAIR_ESTIMATE,
                    "estimate", name + PAIR_ESTIMATE, limits.maxFileBytes());
            return new RunJob(metadata, ref, est, SettingValues.DEFAULTS, name);
        } catch (InputException e) {
            throw new StageException(RunFailure.of(Stage.UNPACK, e), e);
        }
    }

    private static void rejectLink(Path payload, String name) {
        if (Files.isSymbolicLink(payload)) {
            InputException e = new InputException(name, 0, null, InputProblem.PATH_ESCAPES,
                    "a bundle must be a real folder or file, not a symbolic link", null);
            throw new StageException(RunFailure.of(Stage.UNPACK, e), e);
        }
    }

    /** run.yaml sits at the zip's root, or inside its single top-level folder. */
    private static Path manifestFolder(Path root, String name) {
        if (Files.exists(root.resolve(RunManifest.FILE_NAME))) {
            return root;
        }
        Path only = null;
        int count = 0;
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(root)) {
            for (Path p : ds) {
                count++;
                only = p;
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        if (count == 1 && Files.isDirectory(only) && !Files.isSymbolicLink(only)
                && Files.exists(only.resolve(RunManifest.FILE_NAME))) {
            return only;
        }
        InputException e = new InputException(name + ".zip", 0, RunManifest.FILE_NAME, InputProblem.INVALID_CONFIGURATION,
                "zip must hold run.yaml at its root or in its single top-level folder", null);
        throw new StageException(RunFailure.of(Stage.MANIFEST, e), e);
    }
}
