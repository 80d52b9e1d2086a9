package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.trajeval.core.io.bag.BagLimits;
import org.trajeval.core.io.bag.BagSummary;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code trajeval topics BAG}: the topics of a bag (type, count, log-time span) and its TF tree. */
@Command(name = "topics", mixinStandardHelpOptions = true,
        description = {"Lists the topics of a ROS bag (MCAP, ROS 1 bag, rosbag2 sqlite3 file or folder): message type, "
            + "message count, log-time span (s) and whether trajeval reads poses from it; then the TF tree of /tf and "
            + "/tf_static (parent -> child, static or the number of stamps and their span)."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:internal error (a bug; rerun with --verbose)",
            "2:bad input (one line names the file and what is wrong)"})
public final class TopicsCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "BAG", description = "The bag file or rosbag2 folder.")
    Path bag;

    @picocli.CommandLine.Option(names = "--verbose", description = "Print stack traces of errors.")
    boolean verbose;

    @Override
    public Integer call() {
        BagSummary s = BagSummary.of(bag, BagLimits.DEFAULT);
        PrintWriter o = spec.commandLine().getOut();
        o.println(bag + ": " + s.kind() + " bag, " + s.topics().size() + " topics");
        List<String[]> rows = new ArrayList<>();
        rows.add(new String[] {"topic", "type", "messages", "first_log_s", "last_log_s", "span_s", "poses"});
        for (BagSummary.Topic t : s.topics()) {
            rows.add(new String[] {t.topic(), t.type(), Long.toString(t.messages()), seconds(t.firstLogNs()),
                seconds(t.lastLogNs()), String.format(Locale.ROOT, "%.3f", (t.lastLogNs() - t.firstLogNs()) / 1e9),
                t.poses() ? "yes" : "no"});
        }
        table(o, rows);
        if (!s.tf().isEmpty()) {
            o.println();
            o.println("TF tree (use as --ref-topic/--est-topic /tf:PARENT.CHILD):");
            print(o, s.tf(), root(s.tf()), "  ");
        }
        o.flush();
        return ExitCodes.OK;
    }

    private static List<String> root(List<BagSummary.TfEdge> edges) {
        List<String> roots = new ArrayList<>();
        for (BagSummary.TfEdge e : edges) {
            boolean hasParent = edges.stream().anyMatch(f -> f.child().equals(e.parent()));
            if (!hasParent && !roots.contains(e.parent())) {
                roots.add(e.parent());
            }
        }
        return roots;
    }

    private static void print(PrintWriter o, List<BagSummary.TfEdge> edges, List<String> frames, String indent) {
        for (String f : frames) {
            if (indent.length() == 2) {
                o.println(indent + f);
            }
            for (BagSummary.TfEdge e : edges) {
                if (e.parent().equals(f)) {
                    o.println(indent + "  -> " + e.child() + (e.isStatic() ? "  (static)"
                            : String.format(Locale.ROOT, "  (%d stamps, %.3f .. %.3f s)", e.stamps(), e.firstS(),
                                    e.lastS())));
                    print(o, edges, List.of(e.child()), indent + "  ");
                }
            }
        }
    }

    private static String seconds(long ns) {
        return String.format(Locale.ROOT, "%.3f", ns / 1e9);
    }

    private static void table(PrintWriter o, List<String[]> rows) {
        int[] w = new int[rows.get(0).length];
        for (String[] r : rows) {
            for (int i = 0; i < r.length; i++) {
                w[i] = Math.max(w[i], r[i].length());
            }
        }
        for (String[] r : rows) {
            StringBuilder sb = new StringBuilder();
            for (int i = 0; i < r.length; i++) {
                sb.append(i == 0 ? "" : "  ").append(String.format(Locale.ROOT, "%-" + w[i] + "s", r[i]));
            }
            o.println(sb.toString().stripTrailing());
        }
    }
}
