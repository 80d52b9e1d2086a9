package org.trajeval.core.io.bag;

import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DatabaseMetaData;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import org.sqlite.SQLiteConfig;
import org.trajeval.core.io.sqlite.SqliteNativeLibrary;

/**
 * rosbag2 sqlite3 storage ({@code .db3}), read-only through JDBC: table {@code topics} (id, name,
 * type, serialization_format), {@code messages} (topic_id, timestamp in ns, data) read in
 * timestamp order, and {@code message_definitions} when the file has it (rosbag2 9 and later;
 * older files store no definitions and trajeval uses its copy of the standard ones).
 */
final class Sqlite3BagReader implements BagContainer {
    private final String source;
    private final Connection db;
    private final List<BagChannel> channels = new ArrayList<>();

    Sqlite3BagReader(Path path, String source, BagLimits limits) {
        this.source = source;
        try {
            // the driver's native library from a fixed file, not a fresh copy in /tmp at every start
            SqliteNativeLibrary.configure(System.getenv());
        } catch (IllegalStateException e) {
            throw BagProblems.unreadable(source, e.getMessage(), e);
        }
        try {
            SQLiteConfig config = new SQLiteConfig();
            config.setReadOnly(true);
            this.db = config.createConnection("jdbc:sqlite:" + path.toAbsolutePath());
        } catch (SQLException e) {
            throw problem(e);
        }
        try {
            Map<String, String[]> definitions = definitions();
            try (Statement s = db.createStatement();
                    ResultSet r = s.executeQuery("SELECT id, name, type, serialization_format FROM topics ORDER BY id")) {
                while (r.next()) {
                    String name = r.getString(2);
                    String type = r.getString(3);
                    if (name == null || type == null) {
                        throw BagProblems.corrupt(source, -1, "row " + r.getInt(1) + " of table topics has no "
                                + (name == null ? "name" : "type"));
                    }
                    String[] def = definitions.getOrDefault(type, new String[] {"", ""});
                    channels.add(new BagChannel(r.getInt(1), name, type, def[0], def[1],
                            r.getString(4) == null ? "" : r.getString(4)));
                }
            }
        } catch (SQLException e) {
            close();
            throw problem(e);
        } catch (RuntimeException e) {
            close(); // a refused file (a topics row without a name) must not keep its connection and file open
            throw e;
        }
    }

    private Map<String, String[]> definitions() throws SQLException {
        Map<String, String[]> out = new HashMap<>();
        DatabaseMetaData meta = db.getMetaData();
        try (ResultSet t = meta.getTables(null, null, "message_definitions", null)) {
            if (!t.next()) {
                return out;
            }
        }
        try (Statement s = db.createStatement(); ResultSet r = s.executeQuery(
                "SELECT topic_type, encoding, encoded_message_definition FROM message_definitions")) {
            while (r.next()) {
                String enc = r.getString(2);
                String text = r.getString(3);
                if (r.getString(1) != null && text != null && !text.isEmpty() && ("ros2msg".equals(enc) || "ros2idl".equals(enc))) {
                    out.put(r.getString(1), new String[] {enc, text});
                }
            }
        }
        return out;
    }

    private org.trajeval.core.InputException problem(SQLException e) {
        return BagProblems.corrupt(source, -1, "not a readable rosbag2 sqlite3 database (" + e.getMessage() + ")");
    }

    @Override
    public String kind() {
        return "rosbag2 sqlite3";
    }

    @Override
    public List<BagChannel> channels() {
        return List.copyOf(channels);
    }

    @Override
    public void read(Predicate<BagChannel> wanted, MessageSink sink) {
        Map<Integer, BagChannel> want = new HashMap<>();
        for (BagChannel c : channels) {
            if (wanted.test(c)) {
                want.put(c.id(), c);
            }
        }
        if (want.isEmpty()) {
            return;
        }
        StringBuilder in = new StringBuilder();
        for (int i = 0; i < want.size(); i++) {
            in.append(i == 0 ? "?" : ",?");
        }
        String sql = "SELECT topic_id, timestamp, data FROM messages WHERE topic_id IN (" + in
                + ") ORDER BY timestamp, id";
        try (PreparedStatement s = db.prepareStatement(sql)) {
            int k = 1;
            for (int id : want.keySet()) {
                s.setInt(k++, id);
            }
            try (ResultSet r = s.executeQuery()) {
                while (r.next()) {
                    byte[] data = r.getBytes(3);
                    if (data == null) {
                        data = new byte[0];
                    }
                    sink.message(want.get(r.getInt(1)), r.getLong(2), data, 0, data.length);
                }
            }
        } catch (SQLException e) {
            throw problem(e);
        }
    }

    @Override
    public void close() {
        try {
            db.close();
        } catch (SQLException e) {
            // read-only connection: nothing was written that could be lost
        }
    }
}
