-- trajeval results store, schema v1: one row per recorded run result, free tags beside it.
-- Immutable once released: a change is a new file V2__..., never an edit (the store refuses a
-- database whose applied migration's SHA-256 differs from this file's).
-- Plain SQL that SQLite and PostgreSQL both accept.
CREATE TABLE runs (
    result_sha256     CHAR(64)         NOT NULL PRIMARY KEY,
    origin            VARCHAR(16)      NOT NULL,
    run_id            TEXT,
    run_version       INTEGER,
    content_sha256    CHAR(64),
    dataset           TEXT,
    robot             TEXT,
    site              TEXT,
    route             TEXT,
    method            TEXT,
    software_version  TEXT,
    seed              BIGINT,
    recorded_at       TEXT             NOT NULL,
    recorded_ms       BIGINT           NOT NULL,
    status            VARCHAR(8)       NOT NULL,
    failure_reason    TEXT,
    coverage          DOUBLE PRECISION,
    ate_trans_rmse_m  DOUBLE PRECISION,
    ate_trans_mean_m  DOUBLE PRECISION,
    ate_rot_rmse_rad  DOUBLE PRECISION,
    rpe_trans_rmse_m  DOUBLE PRECISION,
    rpe_rot_rmse_rad  DOUBLE PRECISION,
    drift_trans_pct   DOUBLE PRECISION,
    score             DOUBLE PRECISION,
    source            TEXT
);
CREATE TABLE run_tags (
    result_sha256     CHAR(64)         NOT NULL REFERENCES runs (result_sha256),
    tag               TEXT             NOT NULL,
    value             TEXT             NOT NULL,
    PRIMARY KEY (result_sha256, tag)
);
CREATE INDEX runs_by_version ON runs (software_version, method, route, seed);
CREATE INDEX runs_by_time ON runs (recorded_ms);
CREATE INDEX runs_by_robot ON runs (robot, recorded_ms);
CREATE INDEX runs_by_route ON runs (route, recorded_ms);
CREATE INDEX run_tags_by_value ON run_tags (tag, value);
