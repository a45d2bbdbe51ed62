import { useState } from 'react';
import { Live } from '../app/Live.tsx';
import { useI18n, type MessageKey } from '../i18n/i18n.tsx';
import { CsvExport } from './CsvExport.tsx';
import { RewindBar } from './RewindBar.tsx';
import type { Rewind } from './use-rewind.ts';

const CSV_MESSAGES: Record<'copied' | 'downloaded' | 'failed', MessageKey> = {
  copied: 'lab.csvCopied',
  downloaded: 'lab.csvDownloaded',
  failed: 'lab.csvFailed',
};

/** Props of {@link DataTools}. */
export interface DataToolsProps {
  /** The screen's {@link useRewind}. */
  readonly rewind: Rewind;
  /** Name of the downloaded file, e.g. "newton-forces.csv". */
  readonly fileName: string;
  /** True while the simulation runs on a shown screen: the bar follows the saved moments. */
  readonly live: boolean;
  /** Tells screen readers what the export did. */
  readonly announce: (text: string, assertive?: boolean) => void;
}

/**
 * A screen's data tools: step back and scrub through the last seconds, and the measurements as
 * CSV, copied or downloaded, with a line saying how many rows went.
 */
export function DataTools({ rewind, fileName, live, announce }: DataToolsProps) {
  const { t } = useI18n();
  const [status, setStatus] = useState('');
  return (
    <div data-lab="data" className="data-tools">
      <p className="ui-caption ui-secondary">{t('lab.data')}</p>
      <Live active={live} watch={rewind.key}>
        {() => (
          <RewindBar
            length={rewind.length}
            index={rewind.index}
            timeAt={rewind.timeAt}
            onSeek={rewind.seek}
          />
        )}
      </Live>
      <CsvExport
        csv={() => rewind.log.toCsv()}
        fileName={fileName}
        onDone={(outcome) => {
          const text = t(CSV_MESSAGES[outcome], { rows: rewind.log.length });
          setStatus(text);
          announce(text, true);
        }}
      />
      {status !== '' && (
        <span className="ui-caption" data-readout="csv-status">
          {status}
        </span>
      )}
    </div>
  );
}
