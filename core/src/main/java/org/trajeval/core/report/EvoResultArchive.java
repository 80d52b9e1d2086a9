package org.trajeval.core.report;

import org.trajeval.core.InputException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;

/**
 * Reads an evo {@code --save_results} archive: a zip with {@code info.json} (title, label),
 * {@code stats.json} (rmse, mean, median, std, min, max, sse) and the per-value errors as numpy
 * arrays ({@code error_array}, optional {@code timestamps}; each a {@code .npy}, or a
 * {@code .npz} holding one). The title names the error ("APE w.r.t. translation part (m)",
 * "RPE w.r.t. rotation angle in degrees (deg)"); angles in degrees are converted to rad.
 */
public final class EvoResultArchive {
    /** Largest entry read (bytes): a length in a file is a claim, not a fact. */
    static final long MAX_ENTRY_BYTES = 1L << 30;
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Pattern SHAPE = Pattern.compile("'shape':\\s*\\((\\d+),?\\s*\\)");

    private EvoResultArchive() {
    }

    /**
     * @param name the name to give the result
     * @throws InputException naming the archive and the entry when it is not an evo result
     */
    public static ResultSet read(Path zip, String name) {
        Map<String, byte[]> entries = entries(zip);
        JsonNode info = json(zip, entries, "info.json");
        JsonNode stats = json(zip, entries, "stats.json");
        String title = info.path("title").asText("");
        ResultSet.Kind kind = kind(zip, title);
        boolean degrees = title.contains("in degrees");
        double f = degrees ? Math.PI / 180.0 : 1.0;
        double[] values = array(zip, entries, "error_array");
        if (values == null) {
            throw InputException.unreadable(zip + ": no error_array.npy or error_array.npz entry; not an evo "
                    + "--save_results archive");
        }
        double[] t = array(zip, entries, "timestamps");
        if (t != null && t.length == values.length && t.length > 0) {
            double t0 = t[0];
            for (int i = 0; i < t.length; i++) {
                t[i] -= t0;
            }
        } else {
            t = null;
        }
        for (int i = 0; i < values.length; i++) {
            values[i] *= f;
        }
        EvaluationReport.Stats s = new EvaluationReport.Stats(num(stats, "rmse", f), num(stats, "mean", f),
                num(stats, "median", f), num(stats, "std", f), num(stats, "min", f), num(stats, "max", f),
                num(stats, "sse", f * f), values.length);
        return new ResultSet(name, zip.toString(), "evo", title.replace('\n', ' '), t == null ? null : "s",
                List.of(new ResultSet.Errors(kind, s, t, values)));
    }

    static ResultSet.Kind kind(Path zip, String title) {
        boolean ape = title.startsWith("APE");
        boolean rpe = title.startsWith("RPE");
        boolean trans = title.contains("translation part");
        boolean rot = title.contains("rotation angle");
        if ((ape || rpe) && (trans || rot)) {
            return ape ? (trans ? ResultSet.Kind.ATE_TRANS : ResultSet.Kind.ATE_ROT)
                    : (trans ? ResultSet.Kind.RPE_TRANS : ResultSet.Kind.RPE_ROT);
        }
        throw InputException.unreadable(zip + ": info.json title expected \"APE|RPE w.r.t. translation part|"
                + "rotation angle ...\", found \"" + title.replace("\n", "\\n") + "\"");
    }

    private static Map<String, byte[]> entries(Path zip) {
        Map<String, byte[]> out = new HashMap<>();
        try (ZipInputStream z = new ZipInputStream(Files.newInputStream(zip))) {
            ZipEntry e;
            while ((e = z.getNextEntry()) != null) {
                if (!e.isDirectory()) {
                    out.put(Path.of(e.getName()).getFileName().toString(), bounded(z, zip, e.getName()));
                }
            }
        } catch (IOException e) {
            throw InputException.unreadable(zip + ": not a readable zip archive (" + e.getMessage() + ")", e);
        }
        if (out.isEmpty()) {
            throw InputException.unreadable(zip + ": not a zip archive or empty; evo --save_results archive "
                    + "expected");
        }
        return out;
    }

    private static byte[] bounded(InputStream in, Path zip, String entry) throws IOException {
        byte[] b = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 8, MAX_ENTRY_BYTES + 1));
        if (b.length > MAX_ENTRY_BYTES) {
            throw InputException.unreadable(zip + ": entry " + entry + " is larger than " + MAX_ENTRY_BYTES
                    + " bytes");
        }
        return b;
    }

    private static JsonNode json(Path zip, Map<String, byte[]> entries, String name) {
        byte[] b = entries.get(name);
        if (b == null) {
            throw InputException.unreadable(zip + ": no " + name + " entry; not an evo --save_results archive");
        }
        try {
            return JSON.readTree(new String(b, StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw InputException.unreadable(zip + ": " + name + " is not JSON", e);
        }
    }

    private static Double num(JsonNode stats, String key, double f) {
        JsonNode v = stats.get(key);
        return v == null || !v.isNumber() ? null : v.asDouble() * f;
    }

    /** @return the array stored as NAME.npy or inside NAME.npz, or null when neither is there */
    private static double[] array(Path zip, Map<String, byte[]> entries, String name) {
        for (String file : new String[] {name + ".npy", name + ".npz"}) {
            byte[] b = entries.get(file);
            if (b == null) {
                continue;
            }
            if (b.length > 2 && b[0] == 'P' && b[1] == 'K') {
                try (ZipInputStream z = new ZipInputStream(new ByteArrayInputStream(b))) {
                    ZipEntry e = z.getNextEntry();
                    if (e == null) {
                        throw InputException.unreadable(zip + ": " + file + " is an empty npz archive");
                    }
                    return npy(zip, file + "/" + e.getName(), bounded(z, zip, file));
                } catch (IOException e) {
                    throw InputException.unreadable(zip + ": " + file + " is not a readable npz", e);
                }
            }
            return npy(zip, file, b);
        }
        return null;
    }

    /** numpy's .npy format 1.0/2.0, one-dimensional little-endian float64 only. */
    static double[] npy(Path zip, String entry, byte[] b) {
        if (b.length < 12 || (b[0] & 0xff) != 0x93 || b[1] != 'N' || b[2] != 'U' || b[3] != 'M') {
            throw InputException.unreadable(zip + ": " + entry + " is not a numpy .npy array");
        }
        ByteBuffer bb = ByteBuffer.wrap(b).order(ByteOrder.LITTLE_ENDIAN);
        int major = b[6];
        int headerLen = major == 1 ? bb.getShort(8) & 0xffff : bb.getInt(8);
        int start = (major == 1 ? 10 : 12) + headerLen;
        if (headerLen < 0 || start > b.length) {
            throw InputException.unreadable(zip + ": " + entry + ": header length " + headerLen
                    + " runs past the end (" + b.length + " bytes)");
        }
        String header = new String(b, major == 1 ? 10 : 12, headerLen, StandardCharsets.ISO_8859_1);
        Matcher m = SHAPE.matcher(header);
        if (!header.contains("'descr': '<f8'") || header.contains("'fortran_order': True") || !m.find()) {
            throw InputException.unreadable(zip + ": " + entry + ": a one-dimensional '<f8' array expected, "
                    + "found header " + header.trim());
        }
        long n = Long.parseLong(m.group(1));
        if (n * 8 != b.length - start) {
            throw InputException.unreadable(zip + ": " + entry + ": shape (" + n + ",) needs " + (n * 8)
                    + " bytes of data, found " + (b.length - start));
        }
        double[] out = new double[(int) n];
        bb.position(start);
        bb.asDoubleBuffer().get(out);
        return out;
    }
}
