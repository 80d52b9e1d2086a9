package org.trajeval.core.io.bag;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Predicate;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * A rosbag2 folder: {@code metadata.yaml} names the storage ({@code sqlite3} or {@code mcap}) and
 * the storage files, read one after the other as one bag. Channel ids are renumbered
 * ({@code file index * 65536 + id}) so the files' own ids do not collide.
 */
final class Rosbag2Folder implements BagContainer {
    private final List<BagContainer> parts;
    private final String kind;
    private final List<BagChannel> channels = new ArrayList<>();
    /** Per file: the file's channel id to the renumbered channel. */
    private final List<java.util.Map<Integer, BagChannel>> byFile = new ArrayList<>();

    private Rosbag2Folder(List<BagContainer> parts, String kind) {
        this.parts = parts;
        this.kind = kind;
        for (int i = 0; i < parts.size(); i++) {
            java.util.Map<Integer, BagChannel> m = new java.util.HashMap<>();
            for (BagChannel c : parts.get(i).channels()) {
                BagChannel r = renumbered(i, c);
                channels.add(r);
                m.put(c.id(), r);
            }
            byFile.add(m);
        }
    }

    private static BagChannel renumbered(int file, BagChannel c) {
        return new BagChannel(file * 65536 + c.id(), c.topic(), c.type(), c.schemaEncoding(), c.schema(),
                c.messageEncoding());
    }

    /** Opens the storage files the folder's metadata.yaml names. */
    static BagContainer open(Path folder, String source, BagLimits limits, BagIntegrity integrity) {
        Path meta = folder.resolve("metadata.yaml");
        String where = meta.toString();
        JsonNode info;
        try {
            info = new ObjectMapper(new YAMLFactory()).readTree(Files.readAllBytes(meta))
                    .path("rosbag2_bagfile_information");
        } catch (IOException e) {
            throw new InputException(where, 0, null, InputProblem.CORRUPT_BAG, "not a readable rosbag2 metadata.yaml ("
                    + e.getMessage().lines().findFirst().orElse("") + ")", null);
        }
        String storage = info.path("storage_identifier").asText("");
        if (!storage.equals("sqlite3") && !storage.equals("mcap")) {
            throw BagProblems.unsupported(where, "storage_identifier must be sqlite3 or mcap", storage);
        }
        JsonNode files = info.path("relative_file_paths");
        if (!files.isArray() || files.isEmpty()) {
            throw new InputException(where, 0, "relative_file_paths", InputProblem.CORRUPT_BAG,
                    "relative_file_paths must list the storage files", null);
        }
        Path root = folder.toAbsolutePath().normalize();
        List<BagContainer> parts = new ArrayList<>();
        try {
            for (JsonNode f : files) {
                Path p = root.resolve(f.asText()).normalize();
                if (!p.startsWith(root) || f.asText().isEmpty()) {
                    throw new InputException(where, 0, "relative_file_paths", InputProblem.PATH_ESCAPES,
                            "a storage file must lie inside the bag folder", f.asText());
                }
                String name = source + "/" + f.asText();
                if (!Files.isRegularFile(p)) {
                    throw new InputException(name, 0, null, InputProblem.UNREADABLE,
                            "the storage file named in metadata.yaml does not exist", null);
                }
                parts.add(storage.equals("mcap") ? new McapReader(p, name, limits, integrity) : new Sqlite3BagReader(p, name, limits));
            }
        } catch (RuntimeException e) {
            parts.forEach(BagContainer::close);
            throw e;
        }
        return new Rosbag2Folder(parts, "rosbag2 " + storage + " folder");
    }

    @Override
    public String kind() {
        return kind;
    }

    @Override
    public List<BagChannel> channels() {
        return List.copyOf(channels);
    }

    @Override
    public void read(Predicate<BagChannel> wanted, MessageSink sink) {
        for (int i = 0; i < parts.size(); i++) {
            int file = i;
            java.util.Map<Integer, BagChannel> m = byFile.get(i);
            parts.get(i).read(c -> wanted.test(of(m, file, c)), (c, t, d, o, l) -> sink.message(of(m, file, c), t, d, o, l));
        }
    }

    /** The renumbered channel (channels a linear scan finds late are renumbered on the way). */
    private static BagChannel of(java.util.Map<Integer, BagChannel> m, int file, BagChannel c) {
        BagChannel r = m.get(c.id());
        return r != null ? r : renumbered(file, c);
    }

    @Override
    public void close() {
        parts.forEach(BagContainer::close);
    }
}
