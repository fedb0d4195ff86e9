/**
 * The results folder: the names of its files ({@link sitcov.results.ResultsFolder}), its
 * {@link sitcov.results.Manifest}, the lock that keeps one writer ({@link sitcov.results.FolderLock}), the
 * journal written as an experiment goes and read back by a resume, a merge or a replay
 * ({@link sitcov.results.JournalWriter}, {@link sitcov.results.JournalFiles}, every row checked by
 * {@link sitcov.results.JournalCheck}; {@link sitcov.results.ResultsRows} finds a run again), and the
 * columns of its tables, one {@link sitcov.results.Columns} list each that both writes a table and reads it
 * back by header name ({@link sitcov.results.RunsCsv}, {@link sitcov.results.DriversCsv},
 * {@link sitcov.results.TimingsCsv}, {@link sitcov.results.StatsCsv}, {@link sitcov.results.ResultsTables};
 * {@link sitcov.results.CsvTable} reads one back by column name). Every file is written whole
 * ({@link sitcov.results.OutputFile}), and a failure is named with its reason ({@link sitcov.results.IoReason}).
 */
package sitcov.results;
