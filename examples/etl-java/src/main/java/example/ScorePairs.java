package example;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.trajeval.api.TrajectoryEvaluator;
import org.trajeval.core.InputException;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;

/**
 * An ETL step: reads a table of (name, reference, estimate) pairs, scores every pair in-process,
 * writes one JSON report per pair (OUT_DIR/NAME.json) and a summary (OUT_DIR/summary.csv).
 *
 * <pre>
 * score-pairs PAIRS.csv OUT_DIR
 * PAIRS.csv: a header line "name,reference,estimate", then one pair per line; relative paths are
 *            taken from the table's folder; names are file-name safe ([A-Za-z0-9._-]).
 * exit 0: every pair scored; 2: some pair refused (its row says why), the others are written.
 * </pre>
 */
public final class ScorePairs {
    private static final String HEADER = "name,status,ate_trans_rmse_m,ate_rot_rmse_rad,rpe_trans_rmse_m,"
            + "rpe_rot_rmse_rad,matched,message";

    private ScorePairs() {
    }

    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: score-pairs PAIRS.csv OUT_DIR");
            System.exit(2);
        }
        Path table = Path.of(args[0]);
        Path out = Path.of(args[1]);
        List<Pair> pairs = readPairs(table);
        Files.createDirectories(out);

        // one evaluator for the whole job: immutable and safe to share between threads; the settings
        // are trajeval eval's and run.yaml's (here the default convention, written out)
        TrajectoryEvaluator evaluator = TrajectoryEvaluator.of(Map.of("convention", "lesson"));
        List<String> rows = pairs.parallelStream().map(p -> score(evaluator, p, out)).toList();

        List<String> summary = new ArrayList<>();
        summary.add(HEADER);
        summary.addAll(rows);
        ReportJson.writeAtomically(out.resolve("summary.csv"), String.join("\n", summary) + "\n");
        boolean refused = rows.stream().anyMatch(r -> r.contains(",refused,"));
        System.exit(refused ? 2 : 0);
    }

    /** Scores one pair: its report file and its summary row, or a "refused" row with the reason. */
    private static String score(TrajectoryEvaluator evaluator, Pair p, Path out) {
        try {
            EvaluationReport r = evaluator.evaluate(p.reference(), p.estimate());
            ReportJson.writeAtomically(out.resolve(p.name() + ".json"), ReportJson.toJson(r) + "\n");
            return String.join(",", p.name(), "scored", num(r.ate().transM().rmse()), num(r.ate().rotRad().rmse()),
                    num(r.rpe().transM().rmse()), num(r.rpe().rotRad().rmse()),
                    Integer.toString(r.association().matched()), "");
        } catch (InputException e) {
            return String.join(",", p.name(), "refused", "", "", "", "", "", quote(e.getMessage()));
        }
    }

    private record Pair(String name, Path reference, Path estimate) {
    }

    private static List<Pair> readPairs(Path table) throws IOException {
        List<String> lines = Files.readAllLines(table, StandardCharsets.UTF_8);
        if (lines.isEmpty() || !lines.get(0).trim().equals("name,reference,estimate")) {
            fail(table + ":1: expected the header \"name,reference,estimate\", found "
                    + (lines.isEmpty() ? "an empty file" : quote(lines.get(0))));
        }
        Path base = table.toAbsolutePath().getParent();
        List<Pair> pairs = new ArrayList<>();
        for (int i = 1; i < lines.size(); i++) {
            String line = lines.get(i).trim();
            if (line.isEmpty()) {
                continue;
            }
            String[] f = line.split(",", -1);
            if (f.length != 3 || !f[0].matches("[A-Za-z0-9._-]+")) {
                fail(table + ":" + (i + 1) + ": expected name,reference,estimate with a file-name safe name, found "
                        + quote(line));
            }
            pairs.add(new Pair(f[0], base.resolve(f[1].trim()), base.resolve(f[2].trim())));
        }
        return pairs;
    }

    private static String num(Double v) {
        return v == null ? "" : v.toString();
    }

    private static String quote(String s) {
        return "\"" + s.replace("\"", "\"\"").replace("\n", " ") + "\"";
    }

    private static void fail(String message) {
        System.err.println("score-pairs: " + message);
        System.exit(2);
    }
}
