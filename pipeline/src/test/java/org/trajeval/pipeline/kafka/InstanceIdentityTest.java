package org.trajeval.pipeline.kafka;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class InstanceIdentityTest {
    @TempDir
    Path root;

    @Test
    void aRestartedInstanceGetsItsIdBackWhileARunningOneKeepsItsOwn() {
        String first;
        String second;
        try (InstanceIdentity a = InstanceIdentity.claim(root); InstanceIdentity b = InstanceIdentity.claim(root)) {
            first = a.id();
            second = b.id();
            assertNotEquals(first, second, "two running instances sharing a root need two transactional ids");
        }
        try (InstanceIdentity again = InstanceIdentity.claim(root)) {
            assertEquals(first, again.id(), "a restart takes the lowest free slot and its stored id");
        }
    }
}
