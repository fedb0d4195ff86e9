/**
 * The accident oracle: the {@link sitcov.oracle.AccidentDetector} stepped after every vehicle moved,
 * its accident events and blame rules, and the {@link sitcov.oracle.RunResult} of a run. The detector
 * and the near-miss watcher keep no final instance fields: a checkpoint copies them field by field
 * ({@link sitcov.engine.ModelCopy}).
 */
package sitcov.oracle;
