// placeholder until the io stage lands; removed with it
