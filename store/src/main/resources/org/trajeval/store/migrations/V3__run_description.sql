-- trajeval results store, schema v3: what a run's data is and what it cost (issue 18). The same
-- fields as a suite manifest's sequence, run.yaml and Kafka run events: domain (sim | real), the
-- simulated scenario it reproduces, the simulator, the taxonomy (environment, modality, ground
-- truth source), the controlled factor levels (name=level;name=level) and the measured resources.
-- All nullable: rows recorded before v3 keep NULL. Immutable once released, like V1 and V2.
ALTER TABLE runs ADD COLUMN domain TEXT;
ALTER TABLE runs ADD COLUMN scenario TEXT;
ALTER TABLE runs ADD COLUMN simulator TEXT;
ALTER TABLE runs ADD COLUMN environment TEXT;
ALTER TABLE runs ADD COLUMN modality TEXT;
ALTER TABLE runs ADD COLUMN ground_truth TEXT;
ALTER TABLE runs ADD COLUMN factors TEXT;
ALTER TABLE runs ADD COLUMN wall_time_s DOUBLE PRECISION;
ALTER TABLE runs ADD COLUMN peak_memory_mib DOUBLE PRECISION;
CREATE INDEX runs_by_domain ON runs (domain, scenario);
