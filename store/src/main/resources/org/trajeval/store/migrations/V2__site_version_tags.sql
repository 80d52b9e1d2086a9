-- trajeval results store, schema v2: selecting by the fleet labels that run.yaml and Kafka run
-- events now carry (site, software_version, tags). Their columns and the run_tags table exist since
-- V1; this adds the index a site selection (gate --baseline site=..., trend --where site=...,
-- --by site) needs. Immutable once released, like V1.
CREATE INDEX runs_by_site ON runs (site, recorded_ms);
