import { useI18n } from '../i18n/i18n.tsx';
import { Button } from '../ui/Button.tsx';
import { CopyIcon, DownloadIcon } from './lab-icons.tsx';

/** Props of {@link CsvExport}. */
export interface CsvExportProps {
  /** The CSV text, made when asked for (a log can be long). */
  readonly csv: () => string;
  /** Name of the downloaded file, e.g. "newton-reactions.csv". */
  readonly fileName: string;
  /** Told what happened ("copied", "downloaded", or "failed" when the clipboard refused). */
  readonly onDone?: (outcome: 'copied' | 'downloaded' | 'failed') => void;
}

/** Saves a CSV file in the browser: a blob behind a temporary link with `download`. */
export function downloadText(text: string, fileName: string, type = 'text/csv'): void {
  const url = URL.createObjectURL(new Blob([text], { type: `${type};charset=utf-8` }));
  const link = document.createElement('a');
  link.href = url;
  link.download = fileName;
  link.style.display = 'none';
  document.body.append(link);
  link.click();
  link.remove();
  // Revoked later: some browsers read the blob after click() returns.
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

/** Two buttons: copy what was measured as CSV, or download it as a file. */
export function CsvExport({ csv, fileName, onDone }: CsvExportProps) {
  const { t } = useI18n();
  return (
    <div className="csv-export">
      <Button
        variant="outlined"
        startIcon={<CopyIcon />}
        data-action="copy-csv"
        onClick={() => {
          const text = csv();
          navigator.clipboard
            .writeText(text)
            .then(() => onDone?.('copied'))
            .catch(() => onDone?.('failed'));
        }}
      >
        {t('lab.copyCsv')}
      </Button>
      <Button
        variant="outlined"
        startIcon={<DownloadIcon />}
        data-action="download-csv"
        onClick={() => {
          downloadText(csv(), fileName);
          onDone?.('downloaded');
        }}
      >
        {t('lab.downloadCsv')}
      </Button>
    </div>
  );
}
