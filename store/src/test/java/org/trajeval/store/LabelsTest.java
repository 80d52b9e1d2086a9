package org.trajeval.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

class LabelsTest {
    @Test
    void theCanonicalTextSortsKeysSoResultKeysAreTheSameInEveryProcess() {
        // Map.copyOf iterates in an order salted per JVM; the text that goes into result keys must not
        Labels a = Labels.parse(List.of("software_version=2.4", "site=hamburg", "robot=bot-1", "shift=night",
                "area=b"));
        Labels b = Labels.parse(List.of("area=b", "shift=night", "robot=bot-1", "site=hamburg",
                "version=2.4"));
        assertEquals("{robot=bot-1, site=hamburg, software_version=2.4}|{area=b, shift=night}", a.canonical());
        assertEquals(a.canonical(), b.canonical());
    }

    @Test
    void methodAndSeedAreLabelsOfAnEvaluationOnly() {
        assertEquals("{method=orb, seed=3}|{}", Labels.parse(List.of("method=orb", "seed=3"), Labels.EVAL_COLUMNS)
                .canonical());
        StoreException suite = assertThrows(StoreException.class, () -> Labels.parse(List.of("method=orb")));
        assertEquals("--tag: 'method' comes from the report itself; a tag may set software_version, robot, site, "
                + "route or a free key", suite.getMessage());
        StoreException seed = assertThrows(StoreException.class,
                () -> Labels.parse(List.of("seed=1.5"), Labels.EVAL_COLUMNS));
        assertEquals(StoreException.Problem.BAD_QUERY, seed.problem());
    }
}
