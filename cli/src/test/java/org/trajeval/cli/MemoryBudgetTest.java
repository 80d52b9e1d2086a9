package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/** A pair too large for the heap is refused before reading, naming the option that raises the heap. */
class MemoryBudgetTest {
    @TempDir
    Path dir;

    private Path csv(String name, int rows) throws IOException {
        StringBuilder sb = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i < rows; i++) {
            sb.append(i * 0.01).append(",1.000000,2.000000,0.100000\n");
        }
        Path p = dir.resolve(name);
        Files.writeString(p, sb);
        return p;
    }

    @Test
    void pairLargerThanTheHeapIsRefusedNamingXmx() throws IOException {
        Path a = csv("a.csv", 10_000);
        Path b = csv("b.csv", 10_000);
        // 20 000 poses x 96 B = 1.9 MB needed; a 1 MB heap cannot hold them
        InputException e = assertThrows(InputException.class, () -> MemoryBudget.check(a, b, 1_000_000));
        assertEquals(InputProblem.TOO_LARGE, e.problem());
        assertTrue(e.getMessage().contains("TRAJEVAL_OPTS=-Xmx"), e.getMessage());
        // the pose count is estimated from the file size: within a few percent of 20 000
        assertTrue(e.getMessage().matches(".*about (19|20|21),\\d{3} poses.*"), e.getMessage());
    }

    @Test
    void aTumPairIsBudgetedAtTheColumnarEvaluatorsCostUnlessEveryPoseIsKept() throws IOException {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < 10_000; i++) {
            sb.append(i * 0.01).append(" 1.000000 2.000000 0.000000 0 0 0 1\n");
        }
        Path a = dir.resolve("a.tum");
        Files.writeString(a, sb);
        // 20 000 poses: x 240 B = 4.8 MB for the columnar evaluator, x 1200 B = 24 MB with plots
        assertDoesNotThrow(() -> MemoryBudget.check(a, a, 8L << 20, false));
        assertThrows(InputException.class, () -> MemoryBudget.check(a, a, 8L << 20, true));
    }

    @Test
    void pairThatFitsIsAccepted() throws IOException {
        Path a = csv("a.csv", 1000);
        assertDoesNotThrow(() -> MemoryBudget.check(a, a, 64L << 20));
    }
}
