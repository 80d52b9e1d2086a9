-- trajeval results store, schema v2: selecting by the fleet labels that run.yaml and Kafka run
-- events now carry (site, software_version, tags). Their columns and the run_tags table exist since
-- V1; this adds the indexes selections by them need. Immutable once released, like V1.
-- A site selection (gate --baseline site=..., trend --where site=..., --by site):
CREATE INDEX runs_by_site ON runs (site, recorded_ms);
-- A gate between software versions reads the pairing keys and the default gated metrics from this
-- index alone (SQLite: 0.20 s instead of 0.55 s of CPU for 10^5 runs a side at 10^6); it starts
-- with V1's runs_by_version, which it replaces.
CREATE INDEX runs_by_version_gate ON runs (software_version, method, route, seed, status, ate_trans_rmse_m,
    rpe_trans_rmse_m);
DROP INDEX runs_by_version;
